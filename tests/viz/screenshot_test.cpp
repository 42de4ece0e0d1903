// Offscreen screenshots of a real replay: the PNG must show a lit robot on the ground.
#include <gtest/gtest.h>

#include <osg/Image>
#include <osgDB/ReadFile>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>

#include "cic/report/preset_replay.hpp"
#include "cic/viz/palette.hpp"
#include "cic/viz/viewer.hpp"
#include "support/child_env.hpp"
#include "support/run_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace cic;

// R1 under a sine gait for 2 s, recorded at 25 fps: the recording the viewer plays.
viz::ViewEntry sine_entry() {
    report::PresetReplay preset;
    preset.robot_type = 1;
    preset.controller = "sine:0.6,0.5";
    preset.sim.sample_to = 2.0;
    preset.sim.delayed_start = 0.0;
    report::ReplayItem item = report::replay_preset(preset, 25.0, false);
    return {{-1, item.label, item.replayed_fitness}, std::move(item.recording), item.centre_body};
}

fs::path temp_png(const std::string& name) {
    return fs::temp_directory_path() / ("cic_viz_test_" + std::to_string(::getpid()) + "_" + name + ".png");
}

// Without an X display the GL tests re-run this binary under xvfb-run (Mesa software GL).
bool rerun_under_xvfb(const std::string& filter, int& status) {
    if (std::getenv("DISPLAY")) return false;
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) return false;
    const std::string self = fs::read_symlink("/proc/self/exe").string();
    const std::string cmd = cic::testing::without_leak_check() + "xvfb-run -a -s '-screen 0 1024x768x24' '" + self + "' --gtest_filter=" + filter;
    status = std::system(cmd.c_str());
    return true;
}

TEST(Screenshot, ShowsALitRobotOnTheGround) {
    int status = 0;
    if (rerun_under_xvfb("Screenshot.ShowsALitRobotOnTheGround", status)) {
        ASSERT_EQ(status, 0) << "the test failed under xvfb-run";
        return;
    }
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY and no xvfb-run";

    const viz::ViewEntry entry = sine_entry();
    const fs::path png = temp_png("robot");
    viz::screenshot(entry, 1.0, 320, 240, png);
    ASSERT_TRUE(fs::exists(png));
    osg::ref_ptr<osg::Image> image = osgDB::readRefImageFile(png.string());
    ASSERT_TRUE(image.valid());
    ASSERT_EQ(image->s(), 320);
    ASSERT_EQ(image->t(), 240);

    std::set<unsigned> colours;
    int orange = 0, blue = 0, ground = 0;
    for (int y = 0; y < image->t(); ++y)
        for (int x = 0; x < image->s(); ++x) {
            const osg::Vec4 c = image->getColor(x, y);
            colours.insert(static_cast<unsigned>(c.r() * 255) << 16 | static_cast<unsigned>(c.g() * 255) << 8 |
                           static_cast<unsigned>(c.b() * 255));
            if (c.r() > 0.3f && c.r() > 1.6f * c.b() && c.g() > 1.2f * c.b()) ++orange;   // chassis
            if (c.b() > 0.3f && c.b() > 1.9f * c.r()) ++blue;                             // panels
            // The checkered ground: grey tiles (the camera looks down on the robot, so
            // the ground fills the frame behind it).
            if (std::abs(c.r() - c.g()) < 0.03f && std::abs(c.g() - c.b()) < 0.03f && c.r() > 0.25f && c.r() < 0.9f)
                ++ground;
        }
    EXPECT_GT(colours.size(), 50u) << "a blank or flat image";
    EXPECT_GT(orange, 200) << "no chassis pixels";
    EXPECT_GT(blue, 20) << "no panel pixels";
    // A fifth at least: the overlay's lines (wrapped to fit the frame, hud_test.cpp) cover the top.
    EXPECT_GT(ground, 320 * 240 / 5) << "no ground around the robot";
    fs::remove(png);
}

// R1 under a sine gait that walks (about 1.5 m in 15 s), recorded at 25 fps.
viz::ViewEntry walking_entry() {
    report::PresetReplay preset;
    preset.robot_type = 1;
    preset.controller = "sine:1.1,1,1.571";
    preset.sim.sample_to = 15.0;
    preset.sim.delayed_start = 0.0;
    report::ReplayItem item = report::replay_preset(preset, 25.0, false);
    viz::ViewEntry e{{-1, item.label, item.replayed_fitness}, std::move(item.recording), item.centre_body};
    e.preferred_axis = item.preferred_axis;
    return e;
}

// Pixels of the trail's colour (palette.hpp's kTrail, unlit) and of the start ring's.
std::pair<int, int> trail_pixels(const osg::Image& image) {
    int trail = 0, ring = 0;
    for (int y = 0; y < image.t(); ++y)
        for (int x = 0; x < image.s(); ++x) {
            const osg::Vec4 c = image.getColor(x, y);
            if (std::abs(c.r() - viz::kTrail[0]) < 0.08f && std::abs(c.g() - viz::kTrail[1]) < 0.08f &&
                std::abs(c.b() - viz::kTrail[2]) < 0.08f)
                ++trail;
            if (std::abs(c.r() - viz::kTrailStart[0]) < 0.08f && std::abs(c.g() - viz::kTrailStart[1]) < 0.08f &&
                std::abs(c.b() - viz::kTrailStart[2]) < 0.08f)
                ++ring;
        }
    return {trail, ring};
}

TEST(Screenshot, DrawsTheTrailAndItsStartWithAFixedCamera) {
    int status = 0;
    if (rerun_under_xvfb("Screenshot.DrawsTheTrailAndItsStartWithAFixedCamera", status)) {
        ASSERT_EQ(status, 0) << "the test failed under xvfb-run";
        return;
    }
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY and no xvfb-run";
    const viz::ViewEntry entry = walking_entry();
    const fs::path with = temp_png("trail"), without = temp_png("notrail"), early = temp_png("early");
    viz::SceneOptions on;   // the defaults: trail on, fixed camera
    viz::screenshot(entry, 15.0, 400, 300, with, on);
    viz::screenshot(entry, 0.5, 400, 300, early, on);
    viz::SceneOptions off = on;
    off.trail = false;
    viz::screenshot(entry, 15.0, 400, 300, without, off);
    const auto [trail, ring] = trail_pixels(*osgDB::readRefImageFile(with.string()));
    const auto [early_trail, early_ring] = trail_pixels(*osgDB::readRefImageFile(early.string()));
    const auto [no_trail, no_ring] = trail_pixels(*osgDB::readRefImageFile(without.string()));
    EXPECT_GT(trail, 30) << "no trail behind a robot that walked";
    EXPECT_GT(ring, 30) << "no ring at the start";
    EXPECT_LT(early_trail, trail) << "the trail should grow as the robot walks";
    EXPECT_EQ(no_trail, 0);
    EXPECT_EQ(no_ring, 0);
    for (const auto& p : {with, without, early}) fs::remove(p);
}

TEST(Screenshot, StripTilesFramesWithTheSameFixedView) {
    int status = 0;
    if (rerun_under_xvfb("Screenshot.StripTilesFramesWithTheSameFixedView", status)) {
        ASSERT_EQ(status, 0) << "the test failed under xvfb-run";
        return;
    }
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY and no xvfb-run";
    const viz::ViewEntry entry = walking_entry();
    const fs::path strip = temp_png("strip"), last = temp_png("last");
    viz::screenshot_strip(entry, {0.5, 3.0, 6.0}, 200, 150, strip);
    viz::screenshot(entry, 6.0, 200, 150, last);
    const osg::ref_ptr<osg::Image> s = osgDB::readRefImageFile(strip.string());
    const osg::ref_ptr<osg::Image> l = osgDB::readRefImageFile(last.string());
    ASSERT_TRUE(s.valid() && l.valid());
    EXPECT_EQ(s->s(), 600);
    EXPECT_EQ(s->t(), 150);
    // The third frame is the still at 6 s, pixel for pixel (the same fixed camera).
    int same = 0;
    for (int y = 0; y < 150; ++y)
        for (int x = 0; x < 200; ++x) same += s->getColor(400 + x, y) == l->getColor(x, y);
    EXPECT_GT(same, 200 * 150 * 95 / 100);
    // The first frame differs: the robot has moved in a view that has not.
    int moved = 0;
    for (int y = 0; y < 150; ++y)
        for (int x = 0; x < 200; ++x) moved += !(s->getColor(x, y) == s->getColor(400 + x, y));
    EXPECT_GT(moved, 500);
    EXPECT_THROW(viz::screenshot_strip(entry, {}, 200, 150, strip), std::invalid_argument);
    EXPECT_THROW(viz::screenshot_strip(entry, {-1.0}, 200, 150, strip), std::invalid_argument);
    fs::remove(strip);
    fs::remove(last);
}

TEST(Screenshot, RejectsBadArguments) {
    viz::ViewEntry entry;
    entry.recording.body_count = 1;
    entry.recording.times = {0.0};
    entry.recording.frames = {{sim::Pose{}}};
    EXPECT_THROW(viz::screenshot(entry, 0.0, 0, 10, temp_png("bad")), std::invalid_argument);
    EXPECT_THROW(viz::screenshot(entry, -1.0, 10, 10, temp_png("bad")), std::invalid_argument);
    EXPECT_THROW(viz::screenshot(entry, 0.0, 10, 10, "x.jpg"), std::invalid_argument);
    entry.centre_body = 3;
    EXPECT_THROW(viz::Viewer({entry}), std::invalid_argument);
    EXPECT_THROW(viz::Viewer({}), std::invalid_argument);
}

// scripts/screenshot-strip.sh on a real (tiny) run: one PNG, the frames side by side.
TEST(Screenshot, StripScriptTilesFramesOfARunsBest) {
    if (!std::getenv("DISPLAY") && std::system("command -v xvfb-run >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "no DISPLAY and no xvfb-run";
    const fs::path dir = cic::testing::temp_dir("strip");
    const auto run = cic::testing::run_settings(dir, "tiny", cic::testing::tiny_hypergp_settings(1, 1));
    ASSERT_EQ(run.rc, 0) << run.log;
    const fs::path png = dir / "strip.png";
    const std::string cmd = cic::testing::without_leak_check() + "CIC='" + cic::testing::cic_binary() + "' '" +
                            std::string(CIC_SOURCE_DIR) + "/scripts/screenshot-strip.sh' '" + run.run.string() +
                            "' '" + png.string() + "' --at '0.5 1 2' --width 160 --height 120 > '" +
                            (dir / "strip.log").string() + "' 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cic::testing::read_text(dir / "strip.log");
    const osg::ref_ptr<osg::Image> image = osgDB::readImageFile(png.string());
    ASSERT_TRUE(image.valid());
    EXPECT_EQ(image->s(), 3 * 160);
    EXPECT_EQ(image->t(), 120);
    // A missing run is refused with exit 2 before anything is written.
    const std::string bad = "'" + std::string(CIC_SOURCE_DIR) + "/scripts/screenshot-strip.sh' '" +
                            (dir / "nothing").string() + "' '" + (dir / "x.png").string() + "' 2>/dev/null";
    EXPECT_EQ(WEXITSTATUS(std::system(bad.c_str())), 2);
    EXPECT_FALSE(fs::exists(dir / "x.png"));
    // RUN "-": what to replay comes from --view (a preset robot under a sine gait).
    const fs::path sine = dir / "sine.png";
    const std::string preset = cic::testing::without_leak_check() + "CIC='" + cic::testing::cic_binary() + "' '" +
                               std::string(CIC_SOURCE_DIR) + "/scripts/screenshot-strip.sh' - '" + sine.string() +
                               "' --at '0.5 1' --width 160 --height 120 --view '--robot R1 --controller "
                               "sine:0.6,0.5' > '" + (dir / "sine.log").string() + "' 2>&1";
    ASSERT_EQ(std::system(preset.c_str()), 0) << cic::testing::read_text(dir / "sine.log");
    const osg::ref_ptr<osg::Image> strip = osgDB::readImageFile(sine.string());
    ASSERT_TRUE(strip.valid());
    EXPECT_EQ(strip->s(), 2 * 160);
    const std::string no_view = "'" + std::string(CIC_SOURCE_DIR) + "/scripts/screenshot-strip.sh' - '" +
                                (dir / "y.png").string() + "' 2>/dev/null";
    EXPECT_EQ(WEXITSTATUS(std::system(no_view.c_str())), 2);
    fs::remove_all(dir);
}

} // namespace
