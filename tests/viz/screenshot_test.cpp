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
    app::PresetReplay preset;
    preset.robot_type = 1;
    preset.controller = "sine:0.6,0.5";
    preset.sim.sample_to = 2.0;
    preset.sim.delayed_start = 0.0;
    app::ReplayItem item = app::replay_preset(preset, 25.0, false);
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
    if (std::system("command -v ffmpeg >/dev/null 2>&1") != 0) GTEST_SKIP() << "ffmpeg not installed";
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
