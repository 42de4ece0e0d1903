#include "cic/io/povray.hpp"

#include <fmt/format.h>

#include <algorithm>
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
    write_text(out_dir / "camera.inc", camera_inc());
    write_text(out_dir / "ground.inc", ground_inc(options.tile > 0 ? options.tile : auto_tile(recording)));

    const int count = resampled_frame_count(recording, fps);
    const double t0 = recording_start(recording);
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
        write_text(out_dir / fmt::format("frame_{:05d}.pov", k), text);
    }
    return count;
}

} // namespace cic::io
