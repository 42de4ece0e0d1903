#include "cic/io/povray.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>
#include <fstream>
#include <stdexcept>

#include "cic/core/error.hpp"
#include "cic/sim/recording_sampler.hpp"

namespace cic::io {

// Pose arithmetic shared with the viewer (sim/recording_sampler.hpp).
using sim::Mat3;
using sim::Vec3;
using sim::check_recording;
using sim::compose;
using sim::recording_start;
using sim::resampled_frame_count;
using sim::robot_radius;
using sim::rotation_matrix;
using sim::sample_frame;
namespace {

namespace fs = std::filesystem;

// ODE (x, y, z) -> POV-Ray (x, z, y).
std::string pov_vector(const Vec3& v) { return fmt::format("<{:.6f}, {:.6f}, {:.6f}>", v[0], v[2], v[1]); }

void write_text(const fs::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw InputError("cannot write POV-Ray file", file.string());
}

std::string materials_inc() {
    // Chassis and panel colours match the OpenSceneGraph viewer (viz/palette.hpp).
    return R"(// cic: materials shared by every frame
#declare CicFinish = finish { ambient 0.12 diffuse 0.75 specular 0.25 roughness 0.04 }
#declare CicChassis = texture { pigment { rgb <0.92, 0.55, 0.12> } finish { CicFinish } }
#declare CicPanel = texture { pigment { rgb <0.20, 0.40, 0.85> } finish { CicFinish } }
#declare CicGroundA = rgb <0.82, 0.82, 0.80>;
#declare CicGroundB = rgb <0.55, 0.57, 0.60>;
)";
}

std::string lights_inc() {
    // A sun placed relative to the robot, so its shadow stays in view, plus a soft fill light.
    return R"(// cic: lights; needs CicCentre and CicRadius
light_source { CicCentre + <9, 11, -3.5> * CicRadius rgb <1.0, 0.97, 0.92> }
light_source { CicCentre + <-6, 4, -3> * CicRadius rgb 0.3 shadowless }
)";
}

// A camera fixed on the world, looking at `focus` from `distance` away (as the
// viewer's fixed camera: from above and behind, viz/scene.cpp).
std::string fixed_camera_inc(const Vec3& focus, double distance) {
    const double n = std::sqrt(1.2 * 1.2 + 2.0 * 2.0 + 1.9 * 1.9);
    return fmt::format(R"(// cic: camera fixed on the world, framing the centre's whole path
#declare CicFocus = {};
camera {{
  location CicFocus + <{:.6f}, {:.6f}, {:.6f}>
  look_at CicFocus
  right x * image_width / image_height
  angle 50
}}
)",
                       pov_vector(focus), 1.2 / n * distance, 2.0 / n * distance, -1.9 / n * distance);
}

// The centre's path up to frame `upto` (its positions at the frames so far) as
// a magenta line on the ground, and a green ring at its start.
std::string trail_text(const std::vector<Vec3>& path, std::size_t upto, double radius, double tile) {
    const double lift = 0.004 * radius, width = 0.12 * tile;
    auto ground = [&](const Vec3& p) { return fmt::format("<{:.6f}, {:.6f}, {:.6f}>", p[0], lift, p[1]); };
    std::string text = fmt::format("torus {{ {:.6f}, {:.6f} translate {} pigment {{ rgb <0.10, 0.55, 0.20> }} "
                                   "finish {{ ambient 0.4 }} }}\n",
                                   0.41 * tile, 0.09 * tile, ground(path.front()));
    const std::size_t n = std::min(upto + 1, path.size());
    if (n < 2) return text;
    // At most 200 points: a long video would otherwise write every frame's whole path.
    const std::size_t step = std::max<std::size_t>(1, n / 200);
    std::vector<Vec3> points;
    for (std::size_t k = 0; k < n; k += step) points.push_back(path[k]);
    if (points.size() < 2 || points.back() != path[n - 1]) points.push_back(path[n - 1]);
    text += fmt::format("sphere_sweep {{ linear_spline {}", points.size());
    for (const Vec3& p : points) text += fmt::format(",\n  {}, {:.6f}", ground(p), width / 2);
    text += "\n  pigment { rgb <0.85, 0.05, 0.55> } finish { ambient 0.5 } no_shadow }\n";
    return text;
}

std::string camera_inc() {
    // Follows the robot centre horizontally; the height stays put so the horizon does not bob.
    return R"(// cic: camera following the robot; needs CicCentre and CicRadius
#declare CicFocus = <CicCentre.x, 0.35 * CicRadius, CicCentre.z>;
camera {
  location CicFocus + <1.6, 0.8, -2.4> * CicRadius
  look_at CicFocus
  right x * image_width / image_height
  angle 50
}
)";
}

std::string ground_inc(double tile) {
    return fmt::format(R"(// cic: ground plane and sky
plane {{ y, 0
  texture {{ pigment {{ checker CicGroundA CicGroundB scale {:.6f} }} finish {{ ambient 0.15 diffuse 0.8 }} }}
}}
sky_sphere {{ pigment {{ gradient y color_map {{ [0 rgb <0.78, 0.86, 0.97>] [1 rgb <0.30, 0.50, 0.85>] }} }} }}
)",
                       tile);
}

std::string box_text(const sim::Part& part, const sim::Pose& world) {
    // POV-Ray local box: ODE local axes with y and z swapped, like the world.
    const double hx = part.size[0] / 2, hy = part.size[2] / 2, hz = part.size[1] / 2;
    const Mat3 r = rotation_matrix(world.quat);
    // R_pov = S R S with S swapping indices 1 and 2.
    auto rp = [&](int i, int j) {
        static const int s[3] = {0, 2, 1};
        return r[static_cast<std::size_t>(s[i] * 3 + s[j])];
    };
    // POV's matrix takes the columns of R_pov, then the translation.
    return fmt::format(
        "box {{ <{:.6f}, {:.6f}, {:.6f}>, <{:.6f}, {:.6f}, {:.6f}> texture {{ {} }}\n"
        "  matrix <{:.6f}, {:.6f}, {:.6f}, {:.6f}, {:.6f}, {:.6f}, {:.6f}, {:.6f}, {:.6f}, "
        "{:.6f}, {:.6f}, {:.6f}> }}\n",
        -hx, -hy, -hz, hx, hy, hz, part.kind == sim::PartKind::Chassis ? "CicChassis" : "CicPanel",
        rp(0, 0), rp(1, 0), rp(2, 0), rp(0, 1), rp(1, 1), rp(2, 1), rp(0, 2), rp(1, 2), rp(2, 2),
        world.pos[0], world.pos[2], world.pos[1]);
}

double auto_tile(const sim::Recording& rec) {
    double edge = 0;
    for (const auto& part : rec.parts) edge = std::max({edge, part.size[0], part.size[1], part.size[2]});
    return edge > 0 ? 2 * edge : 0.5;
}

} // namespace

int write_povray(const sim::Recording& recording, const fs::path& out_dir, double fps,
                 const PovrayOptions& options) {
    if (!(fps > 0)) throw std::invalid_argument("write_povray: fps must be positive");
    check_recording(recording);
    if (options.centre_body < 0 || options.centre_body >= recording.body_count)
        throw std::invalid_argument("write_povray: centre_body out of range");
    if (options.tile < 0) throw std::invalid_argument("write_povray: tile must not be negative");

    std::error_code ec;
    fs::create_directories(out_dir, ec);
    if (ec) throw InputError("cannot create output folder: " + ec.message(), out_dir.string());
    for (const auto& entry : fs::directory_iterator(out_dir)) {
        const std::string name = entry.path().filename().string();
        if (name.starts_with("frame_") && entry.path().extension() == ".pov")
            throw InputError("folder already holds POV-Ray frames (" + name +
                                 "); choose an empty folder so no stale frame ends up in the video",
                             out_dir.string());
    }

    const double radius = robot_radius(recording, options.centre_body);
    write_text(out_dir / "materials.inc", materials_inc());
    write_text(out_dir / "lights.inc", lights_inc());
    const double tile = options.tile > 0 ? options.tile : auto_tile(recording);
    const int count = resampled_frame_count(recording, fps);
    const double t0 = recording_start(recording);
    // The centre on the ground plane (x, y) at every frame: the trail and the fixed camera's frame.
    std::vector<Vec3> path;
    double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
    for (int k = 0; k < count; ++k) {
        const auto c = sample_frame(recording, t0 + k / fps)[static_cast<std::size_t>(options.centre_body)].pos;
        path.push_back({c[0], c[1], 0.0});
        lo_x = std::min(lo_x, c[0]), hi_x = std::max(hi_x, c[0]), lo_y = std::min(lo_y, c[1]), hi_y = std::max(hi_y, c[1]);
    }
    if (options.fixed_camera) {
        const double half = 0.5 * std::max(hi_x - lo_x, hi_y - lo_y) + radius;
        const double distance = std::max(1.15 * half / std::tan(25.0 * M_PI / 180), 3.1 * radius);
        write_text(out_dir / "camera.inc",
                   fixed_camera_inc({(lo_x + hi_x) / 2, (lo_y + hi_y) / 2, 0.35 * radius}, distance));
    } else {
        write_text(out_dir / "camera.inc", camera_inc());
    }
    write_text(out_dir / "ground.inc", ground_inc(tile));

    for (int k = 0; k < count; ++k) {
        const double t = t0 + k / fps;
        const auto bodies = sample_frame(recording, t);
        std::string text = fmt::format("// cic frame {} of {}, t = {:.4f} s{}\n#version 3.7;\n"
                                       "global_settings {{ assumed_gamma 1.0 }}\n",
                                       k + 1, count, t, options.title.empty() ? "" : ", " + options.title);
        text += fmt::format("#declare CicCentre = {};\n#declare CicRadius = {:.6f};\n",
                            pov_vector(bodies[static_cast<std::size_t>(options.centre_body)].pos), radius);
        text += "#include \"materials.inc\"\n#include \"lights.inc\"\n#include \"camera.inc\"\n"
                "#include \"ground.inc\"\n";
        for (const auto& part : recording.parts)
            text += box_text(part, compose(bodies[static_cast<std::size_t>(part.body)], part.offset));
        if (options.trail) text += trail_text(path, static_cast<std::size_t>(k), radius, tile);
        write_text(out_dir / fmt::format("frame_{:05d}.pov", k), text);
    }
    return count;
}

} // namespace cic::io
