// Every input of a run is checked before its folder exists (issue 10): bad
// population files, robot files and text XML cannot hold are refused with exit
// code 2 and file:line, nothing is written, and `cic settings FILE` runs the
// same checks. Paths are resolved once and stored absolute.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <regex>

#include "support/run_helpers.hpp"

namespace cic {
namespace {

using namespace cic::testing;
namespace fs = std::filesystem;

class RunInputs : public ::testing::Test {
protected:
    void SetUp() override {
        dir = temp_dir(std::string("inputs-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    }
    void TearDown() override { fs::remove_all(dir); }

    // A good population to corrupt: the tiny HyperGP run's checkpoint.
    std::string good_population() {
        const auto r = run_settings(dir, "good", tiny_hypergp_settings(2, 1));
        EXPECT_EQ(r.rc, 0) << r.log;
        return read_text(r.run / "population.xml");
    }

    // `cic [settings] --settings tiny.xml EXTRA`: the exit code; output in `log`.
    int run_with(const std::string& extra, bool settings_command = false) {
        write_text(dir / "tiny.xml", tiny_hypergp_settings(2, 1));
        const std::string args = settings_command
            ? "settings " + (dir / "tiny.xml").string() + " " + extra
            : "--quiet --settings " + (dir / "tiny.xml").string() + " --output " + (dir / "out").string() + " " + extra;
        const int rc = run_command(args, dir / "log");
        log = read_text(dir / "log");
        return rc;
    }

    fs::path dir;
    std::string log;
};

std::string replace_first(std::string text, const std::string& pattern, const std::string& with) {
    return std::regex_replace(text, std::regex(pattern), with, std::regex_constants::format_first_only);
}

TEST_F(RunInputs, BadPopulationFilesAreRefusedBeforeAFolderExists) {
    const std::string good = good_population();
    ASSERT_NE(good.find("<individual "), std::string::npos);
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"truncated", good.substr(0, good.size() / 2)},
        {"broken-tree", replace_first(good, "<tree>\\(", "<tree>((")},
        {"nan-fitness", replace_first(good, "fitness=\"[^\"]*\"", "fitness=\"nan\"")},
        {"inf-fitness", replace_first(good, "fitness=\"[^\"]*\"", "fitness=\"inf\"")},
        {"negative-generation", replace_first(good, "generation=\"[0-9]+\"", "generation=\"-5\"")},
        {"duplicate-id", std::regex_replace(good, std::regex("<individual id=\"[0-9]+\""), "<individual id=\"7\"")},
        {"zero-rng", replace_first(good, "state=\"[^\"]*\"", "state=\"0 0 0 0\"")},
        {"wrong-experiment", replace_first(good, "experiment=\"hypergp\"", "experiment=\"symreg\"")},
        {"foreign-function", replace_first(good, "<tree>\\(\\w+", "<tree>(tanh")},
        {"too-many", replace_first(good, "count=\"6\"", "count=\"2000000\"")},
    };
    for (const auto& [name, text] : bad) {
        SCOPED_TRACE(name);
        ASSERT_NE(text, good);
        const fs::path file = dir / (name + ".xml");
        write_text(file, text);
        EXPECT_EQ(run_with("--set Control.populationXmlLoadFrom=" + file.string()), 2) << log;
        EXPECT_NE(log.find(file.string() + ":"), std::string::npos) << log;
        EXPECT_NE(log.find("populationXmlLoadFrom"), std::string::npos) << log;
        EXPECT_FALSE(fs::exists(dir / "out")) << "a run folder was created";
        EXPECT_EQ(run_with("--set Control.populationXmlLoadFrom=" + file.string(), true), 2) << log;
    }
}

TEST_F(RunInputs, BadRobotsAreRefusedBeforeAFolderExists) {
    write_text(dir / "brick.xml", R"(<robot name="brick" centre="a" preferred="x">
  <module name="a" x="0" y="0" z="0" axis="fixed" attach="none"/>
  <module name="b" x="1" y="0" z="0" axis="fixed" attach="-x"/>
</robot>
)");
    std::string snake = "<robot name=\"long\" centre=\"0\" preferred=\"x\">\n"
                        "  <module x=\"0\" y=\"0\" z=\"0\" axis=\"fixed\" attach=\"none\"/>\n";
    for (int i = 1; i <= 512; ++i)
        snake += "  <module x=\"" + std::to_string(i) + "\" y=\"0\" z=\"0\" axis=\"z\" attach=\"-x\"/>\n";
    write_text(dir / "long.xml", snake + "</robot>\n");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {(dir / "missing.xml").string(), "cannot read"},
        {(dir / "brick.xml").string(), "brick.xml:1: <Simulator> robotFile: invalid robot: every module is fixed"},
        {(dir / "long.xml").string(), "past the limit of 512 modules per robot"},
    };
    for (const auto& [file, why] : cases) {
        SCOPED_TRACE(file);
        EXPECT_EQ(run_with("--set Simulator.robotFile=" + file), 2) << log;
        EXPECT_NE(log.find(why), std::string::npos) << log;
        EXPECT_NE(log.find("robotFile"), std::string::npos) << log;
        EXPECT_FALSE(fs::exists(dir / "out"));
        EXPECT_EQ(run_with("--set Simulator.robotFile=" + file, true), 2) << log;
    }
}

// Issue 39, class 4: a robot whose physics fails at the first step (here, far
// out at 2e9) would fail every evaluation and end the run with the failure
// fitness as its best; it is refused with the reason, for HyperGP and gait.
TEST_F(RunInputs, ARobotWhosePhysicsCannotStartIsRefused) {
    write_text(dir / "far.xml", R"(<robot name="far" centre="a" preferred="x">
  <module name="a" x="2000000000" y="0" z="0" axis="fixed" attach="none"/>
  <module name="b" x="2000000001" y="0" z="0" axis="z" attach="-x"/>
</robot>
)");
    const std::string file = (dir / "far.xml").string();
    EXPECT_EQ(run_with("--set Simulator.robotFile=" + file), 2) << log;
    EXPECT_NE(log.find("physics fails at the first step"), std::string::npos) << log;
    EXPECT_NE(log.find("blow-up"), std::string::npos) << log;
    EXPECT_FALSE(fs::exists(dir / "out"));
    EXPECT_EQ(run_with("--set Simulator.robotFile=" + file, true), 2) << log;
    EXPECT_EQ(run_with("--set Experiment.type=gait --set Simulator.robotFile=" + file), 2) << log;
    EXPECT_NE(log.find("physics fails at the first step"), std::string::npos) << log;
    EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST_F(RunInputs, SettingsThatCannotRunAreRefusedBeforeAFolderExists) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"--set Control.maximumIterations=0", "maximumIterations = \"0\": out of range"},
        {"--set 'Experiment.name=a\x01z'", "U+0001 at byte 1, which an XML file cannot hold"},
        {"--set GP.generatedPopulationSize=1000001", "generatedPopulationSize = \"1000001\": out of range"},
        {"--set GP.terminalVariableCount=5", "HyperGP's CPPF has 4 inputs"},
    };
    for (const auto& [extra, why] : cases) {
        SCOPED_TRACE(extra);
        EXPECT_EQ(run_with(extra), 2) << log;
        EXPECT_NE(log.find(why), std::string::npos) << log;
        EXPECT_FALSE(fs::exists(dir / "out"));
    }
}

TEST_F(RunInputs, RelativePathsFromTheCommandLineAreStoredAbsolute) {
    // Run from another folder with a relative robot file and two workers: the
    // workers, which read the run's settings.xml, must find the same file.
    fs::create_directories(dir / "here" / "robots");
    fs::copy_file(fs::path(CIC_SOURCE_DIR) / "settings" / "robots" / "snake.xml", dir / "here" / "robots" / "s.xml");
    write_text(dir / "here" / "tiny.xml", tiny_hypergp_settings(2, 2));
    const std::string cmd = "cd '" + (dir / "here").string() + "' && '" + cic_binary() +
                            "' --quiet --settings tiny.xml --output out --set Simulator.robotFile=robots/s.xml > '" +
                            (dir / "log").string() + "' 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << read_text(dir / "log");
    const fs::path run = only_run(dir / "here" / "out");
    const std::string stored = (dir / "here" / "robots" / "s.xml").string();
    EXPECT_NE(read_text(run / "settings.xml").find("<robotFile>" + stored + "</robotFile>"), std::string::npos);
    EXPECT_EQ(read_text(run / "population.xml").find("key=\"failed\""), std::string::npos)
        << "evaluations failed: the workers did not find the robot";
    EXPECT_NE(read_text(run / "summary.txt").find("robot snake"), std::string::npos);
    // Replays read the stored path from anywhere.
    EXPECT_EQ(run_command("trace '" + run.string() + "' --out '" + (dir / "t.csv").string() + "'", dir / "trace.log"),
              0)
        << read_text(dir / "trace.log");
}

} // namespace
} // namespace cic

namespace cic {
namespace {

// A full disk can still hold a new folder but not a file in it: the run was
// refused only at its first write, and left an empty run folder behind. Needs
// root, for a small tmpfs (CI runs as root).
TEST(RunFolder, AFullDiskKeepsNoRunFolder) {
    if (::geteuid() != 0) GTEST_SKIP() << "needs root to mount a small tmpfs";
    const auto dir = temp_dir("full-disk");
    const fs::path disk = dir / "disk";
    fs::create_directories(disk);
    if (std::system(("mount -t tmpfs -o size=256k tmpfs '" + disk.string() + "'").c_str()) != 0)
        GTEST_SKIP() << "cannot mount a tmpfs here";
    // Fill it: write until the disk refuses.
    {
        std::FILE* f = std::fopen((disk / "filler").c_str(), "wb");
        ASSERT_NE(f, nullptr);
        const std::string block(4096, 'x');
        while (std::fwrite(block.data(), 1, block.size(), f) == block.size() && std::fflush(f) == 0) {
        }
        std::fclose(f);
    }
    fs::create_directories(disk / "out");   // a folder still fits
    write_text(dir / "tiny.xml", tiny_hypergp_settings(2, 1));
    const int rc = run_command("--quiet --settings " + (dir / "tiny.xml").string() + " --output " +
                                   (disk / "out").string(),
                               dir / "log");
    const std::string log = read_text(dir / "log");
    const bool empty = fs::is_empty(disk / "out");
    std::system(("umount '" + disk.string() + "'").c_str());
    EXPECT_EQ(rc, 2) << log;
    EXPECT_NE(log.find("cannot write in the output folder: No space left on device; nothing was kept"),
              std::string::npos)
        << log;
    EXPECT_TRUE(empty) << "a run folder was left on the full disk";
    fs::remove_all(dir);
}

} // namespace
} // namespace cic
