// POV-Ray export: scene text, argument checks, determinism, and one real render.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "cic/app/preset_replay.hpp"
#include "cic/core/error.hpp"
#include "cic/io/povray.hpp"

namespace {

namespace fs = std::filesystem;
using namespace cic;

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("cic_povray_test_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(dir);
    return dir;
}

std::string slurp(const fs::path& p) {
    std::ostringstream s;
    s << std::ifstream(p).rdbuf();
    return s.str();
}

// Two bodies: a 1 m chassis on body 0, a thin panel on body 1; 1 s at 10 frames/s.
sim::Recording two_bodies() {
    sim::Recording r;
    r.body_count = 2;
    r.parts.push_back({0, 0, sim::PartKind::Chassis, {1, 1, 1}, {}});
    r.parts.push_back({1, 0, sim::PartKind::Panel, {0.17, 1, 1}, {{0.1, 0, 0}, {1, 0, 0, 0}}});
    r.frame_dt = 0.1;
    for (int f = 0; f <= 10; ++f) {
        r.times.push_back(0.1 * f);
        sim::Pose a, b;
        a.pos = {1.0 + 0.1 * f, 2.0, 3.0};
        b.pos = {1.65 + 0.1 * f, 2.0, 3.0};
        const double half = 0.05 * f;   // body 1 turns about z
        b.quat = {std::cos(half), 0, 0, std::sin(half)};
        r.frames.push_back({a, b});
    }
    return r;
}

TEST(Povray, WritesOneSceneAFrameAndTheSharedIncludes) {
    const fs::path dir = fresh_dir("frames");
    const int n = io::write_povray(two_bodies(), dir, 25.0);
    EXPECT_EQ(n, 26);   // 1 s at 25 fps, both ends included
    for (const char* inc : {"camera.inc", "lights.inc", "materials.inc", "ground.inc"})
        EXPECT_TRUE(fs::exists(dir / inc)) << inc;
    EXPECT_TRUE(fs::exists(dir / "frame_00025.pov"));
    EXPECT_FALSE(fs::exists(dir / "frame_00026.pov"));
    const std::string first = slurp(dir / "frame_00000.pov");
    EXPECT_NE(first.find("#include \"camera.inc\""), std::string::npos);
    EXPECT_NE(first.find("texture { CicChassis }"), std::string::npos);
    EXPECT_NE(first.find("texture { CicPanel }"), std::string::npos);
    // ODE (1, 2, 3) is POV-Ray <1, 3, 2>: y and z swap.
    EXPECT_NE(first.find("#declare CicCentre = <1.000000, 3.000000, 2.000000>;"), std::string::npos) << first;
    EXPECT_NE(first.find("1.000000, 3.000000, 2.000000> }"), std::string::npos) << first;
    EXPECT_NE(slurp(dir / "materials.inc").find("#declare CicChassis"), std::string::npos);
    fs::remove_all(dir);
}

TEST(Povray, SameRecordingGivesIdenticalFiles) {
    const fs::path a = fresh_dir("a"), b = fresh_dir("b");
    io::write_povray(two_bodies(), a, 10.0);
    io::write_povray(two_bodies(), b, 10.0);
    for (const auto& entry : fs::directory_iterator(a))
        EXPECT_EQ(slurp(entry.path()), slurp(b / entry.path().filename())) << entry.path();
    fs::remove_all(a);
    fs::remove_all(b);
}

TEST(Povray, RejectsBadArguments) {
    const fs::path dir = fresh_dir("bad");
    EXPECT_THROW(io::write_povray(two_bodies(), dir, 0.0), std::invalid_argument);
    io::PovrayOptions far;
    far.centre_body = 2;
    EXPECT_THROW(io::write_povray(two_bodies(), dir, 25.0, far), std::invalid_argument);
    sim::Recording broken = two_bodies();
    broken.frames[3].pop_back();
    EXPECT_THROW(io::write_povray(broken, dir, 25.0), std::invalid_argument);
    broken = two_bodies();
    broken.times.pop_back();
    EXPECT_THROW(io::write_povray(broken, dir, 25.0), std::invalid_argument);
    // A folder that already holds frames is refused: stale frames would join the video.
    io::write_povray(two_bodies(), dir, 5.0);
    try {
        io::write_povray(two_bodies(), dir, 5.0);
        FAIL() << "expected cic::InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("already holds POV-Ray frames"), std::string::npos) << e.what();
        EXPECT_EQ(e.file(), dir.string());
    }
    fs::remove_all(dir);
}

bool have(const char* tool) { return std::system(("command -v " + std::string(tool) + " >/dev/null 2>&1").c_str()) == 0; }

// A real R1 recording rendered by scripts/render-video.sh at 80x60: PNGs and an MP4 appear,
// and a frame is a picture, not one flat colour.
TEST(Povray, RenderScriptMakesFramesAndAVideo) {
    if (!have("povray") || !have("ffmpeg")) GTEST_SKIP() << "povray or ffmpeg not installed";
    app::PresetReplay preset;
    preset.sim.sample_to = 0.2;
    preset.sim.delayed_start = 0.0;
    const app::ReplayItem item = app::replay_preset(preset, 10.0, false);
    const fs::path dir = fresh_dir("render");
    io::PovrayOptions options;
    options.centre_body = item.centre_body;
    ASSERT_EQ(io::write_povray(item.recording, dir, 10.0, options), 3);

    const std::string script = std::string(CIC_SOURCE_DIR) + "/scripts/render-video.sh";
    const std::string cmd = "'" + script + "' '" + dir.string() + "' --width 80 --height 60 --fps 10 --jobs 2 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    const fs::path png = dir / "frame_00000.png";
    ASSERT_TRUE(fs::exists(png));
    EXPECT_GT(fs::file_size(dir / "out.mp4"), 0u);

    // Decode the PNG with ffmpeg into raw RGB and count its colours.
    const std::string decode = "ffmpeg -loglevel error -i '" + png.string() + "' -f rawvideo -pix_fmt rgb24 -";
    FILE* pipe = popen(decode.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string pixels;
    char buf[4096];
    for (std::size_t got; (got = fread(buf, 1, sizeof buf, pipe)) > 0;) pixels.append(buf, got);
    ASSERT_EQ(pclose(pipe), 0);
    ASSERT_EQ(pixels.size(), 80u * 60u * 3u);
    std::set<std::string> colours;
    int orange = 0;
    for (std::size_t i = 0; i < pixels.size(); i += 3) {
        colours.insert(pixels.substr(i, 3));
        const auto r = static_cast<unsigned char>(pixels[i]), b = static_cast<unsigned char>(pixels[i + 2]);
        if (r > 80 && r > 2 * b) ++orange;
    }
    EXPECT_GT(colours.size(), 20u) << "a flat image";
    EXPECT_GT(orange, 10) << "no robot (chassis) pixels";
    fs::remove_all(dir);
}

} // namespace
