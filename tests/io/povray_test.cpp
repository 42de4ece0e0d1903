// POV-Ray export: scene text, argument checks, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "cic/core/error.hpp"
#include "cic/io/povray.hpp"
#include "support/files.hpp"

namespace {

namespace fs = std::filesystem;
using namespace cic;
using cic::testing::read_text;

fs::path fresh_dir(const std::string& name) { return cic::testing::temp_dir("povray-" + name); }

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
    const std::string first = read_text(dir / "frame_00000.pov");
    EXPECT_NE(first.find("#include \"camera.inc\""), std::string::npos);
    EXPECT_NE(first.find("texture { CicChassis }"), std::string::npos);
    EXPECT_NE(first.find("texture { CicPanel }"), std::string::npos);
    // ODE (1, 2, 3) is POV-Ray <1, 3, 2>: y and z swap.
    EXPECT_NE(first.find("#declare CicCentre = <1.000000, 3.000000, 2.000000>;"), std::string::npos) << first;
    EXPECT_NE(first.find("1.000000, 3.000000, 2.000000> }"), std::string::npos) << first;
    EXPECT_NE(read_text(dir / "materials.inc").find("#declare CicChassis"), std::string::npos);
    fs::remove_all(dir);
}

TEST(Povray, SameRecordingGivesIdenticalFiles) {
    const fs::path a = fresh_dir("a"), b = fresh_dir("b");
    io::write_povray(two_bodies(), a, 10.0);
    io::write_povray(two_bodies(), b, 10.0);
    for (const auto& entry : fs::directory_iterator(a))
        EXPECT_EQ(read_text(entry.path()), read_text(b / entry.path().filename())) << entry.path();
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

// The trail: a ring at the start and, from the second frame on, a line through
// the centre's positions so far (x 1.0 to 1.0 + 0.1 t, y 2.0 in ODE's frame,
// so POV z 2.0); a fixed camera looks at the middle of the whole path.
TEST(Povray, DrawsTheTrailSoFarAndCanFixTheCamera) {
    const fs::path dir = fresh_dir("trail");
    io::PovrayOptions o;
    o.fixed_camera = true;
    ASSERT_EQ(io::write_povray(two_bodies(), dir, 10.0, o), 11);
    const std::string first = read_text(dir / "frame_00000.pov"), last = read_text(dir / "frame_00010.pov");
    EXPECT_NE(first.find("torus {"), std::string::npos);
    EXPECT_EQ(first.find("sphere_sweep"), std::string::npos) << "one point is no line yet";
    EXPECT_NE(last.find("sphere_sweep { linear_spline 11"), std::string::npos) << last;
    EXPECT_NE(last.find("<2.000000, "), std::string::npos) << "the last point: x = 2.0";
    EXPECT_NE(read_text(dir / "camera.inc").find("#declare CicFocus = <1.500000, "), std::string::npos)
        << read_text(dir / "camera.inc");
    // Without the trail, no ring and no line; the following camera as before.
    const fs::path plain = fresh_dir("plain");
    io::PovrayOptions off;
    off.trail = false;
    io::write_povray(two_bodies(), plain, 10.0, off);
    EXPECT_EQ(read_text(plain / "frame_00010.pov").find("torus"), std::string::npos);
    EXPECT_NE(read_text(plain / "camera.inc").find("following the robot"), std::string::npos);
    fs::remove_all(dir);
    fs::remove_all(plain);
}

} // namespace
