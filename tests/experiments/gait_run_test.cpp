// The gait experiment end to end with the real binary: the same bytes for 1 or
// 2 workers, a resume that continues bit for bit, replay commands that work on
// its runs, and a checkpoint of another kind refused before a folder exists.
#include <gtest/gtest.h>

#include "support/run_helpers.hpp"

namespace cic {
namespace {

using namespace cic::testing;
namespace fs = std::filesystem;

// R0 (few joints, fast), 2.5 s simulations, 6 candidates per generation.
std::string gait_settings(const std::string& optimizer, int evaluations, int workers, const std::string& extra = "") {
    return R"(<settings>
  <Experiment><type>gait</type><seed>4</seed><workers>)" + std::to_string(workers) + R"(</workers></Experiment>
  <Gait><optimizer>)" + optimizer + "</optimizer><evaluations>" + std::to_string(evaluations) +
           R"(</evaluations><populationSize>7</populationSize></Gait>
  <Simulator><robot_type>0</robot_type><sample_to>2.5</sample_to><delayed_start>0.5</delayed_start></Simulator>
  <Control>)" + extra + R"(</Control>
</settings>
)";
}

TEST(GaitRun, SameBytesForOneOrTwoWorkersForEveryOptimizer) {
    const auto dir = temp_dir("gait-workers");
    for (const std::string opt : {"cmaes", "xnes", "sade"}) {
        const RunResult one = run_settings(dir, opt + "1", gait_settings(opt, 35, 1));
        const RunResult two = run_settings(dir, opt + "2", gait_settings(opt, 35, 2));
        ASSERT_EQ(one.rc, 0) << one.log;
        ASSERT_EQ(two.rc, 0) << two.log;
        EXPECT_EQ(read_text(one.run / "population.xml"), read_text(two.run / "population.xml")) << opt;
        EXPECT_NE(read_text(one.run / "summary.txt").find("stopped: evaluation budget at generation 4"),
                  std::string::npos)
            << read_text(one.run / "summary.txt");
        EXPECT_NE(read_text(one.run / "stats.csv").find("\n4,"), std::string::npos);
    }
    fs::remove_all(dir);
}

TEST(GaitRun, ResumeContinuesBitForBit) {
    const auto dir = temp_dir("gait-resume");
    const RunResult whole = run_settings(dir, "whole", gait_settings("cmaes", 42, 2));
    const RunResult first = run_settings(dir, "first", gait_settings("cmaes", 21, 2));
    ASSERT_EQ(whole.rc, 0) << whole.log;
    ASSERT_EQ(first.rc, 0) << first.log;
    const RunResult rest = run_settings(
        dir, "rest",
        gait_settings("cmaes", 42, 1,
                      "<populationXmlLoadFrom>" + (first.run / "population.xml").string() + "</populationXmlLoadFrom>"));
    ASSERT_EQ(rest.rc, 0) << rest.log;
    EXPECT_EQ(read_text(rest.run / "population.xml"), read_text(whole.run / "population.xml"));
    fs::remove_all(dir);
}

TEST(GaitRun, ReplayCommandsWorkOnItsRuns) {
    const auto dir = temp_dir("gait-replay");
    const RunResult r = run_settings(dir, "g", gait_settings("cmaes", 14, 1));
    ASSERT_EQ(r.rc, 0) << r.log;
    ASSERT_EQ(run_command("trace " + r.run.string() + " --out " + (dir / "t.csv").string(), dir / "trace.log"), 0)
        << read_text(dir / "trace.log");
    EXPECT_EQ(read_text(dir / "t.csv").rfind("t,out_", 0), 0u);
    ASSERT_EQ(run_command("assess " + r.run.string(), dir / "assess.log"), 0) << read_text(dir / "assess.log");
    // The replayed fitness is the stored champion's.
    const std::string summary = read_text(r.run / "summary.txt");
    const std::string stored = summary.substr(summary.find("fitness ") + 8, 10);
    EXPECT_NE(read_text(dir / "assess.log").find("," + stored), std::string::npos) << read_text(dir / "assess.log");
    ASSERT_EQ(run_command("render " + r.run.string() + " --fps 2 --out " + (dir / "frames").string(), dir / "r.log"), 0)
        << read_text(dir / "r.log");
    EXPECT_TRUE(fs::exists(dir / "frames" / "frame_00000.pov"));
    ASSERT_EQ(run_command("plot " + r.run.string() + " --out " + (dir / "p.svg").string(), dir / "p.log"), 0)
        << read_text(dir / "p.log");
    EXPECT_EQ(run_command("trace " + r.run.string() + " --individual 3", dir / "bad.log"), 2);
    fs::remove_all(dir);
}

TEST(GaitRun, CheckpointOfAnotherKindIsRefusedBeforeAFolderExists) {
    const auto dir = temp_dir("gait-bad");
    const RunResult hgp = run_settings(dir, "h", tiny_hypergp_settings(1, 1));
    ASSERT_EQ(hgp.rc, 0) << hgp.log;
    const RunResult bad = run_settings(
        dir, "bad",
        gait_settings("cmaes", 14, 1,
                      "<populationXmlLoadFrom>" + (hgp.run / "population.xml").string() + "</populationXmlLoadFrom>"));
    EXPECT_EQ(bad.rc, 2);
    EXPECT_NE(bad.log.find("not a cic gait checkpoint"), std::string::npos) << bad.log;
    EXPECT_FALSE(fs::exists(dir / "bad"));
    const RunResult small = run_settings(dir, "small", gait_settings("cmaes", 5, 1));
    EXPECT_EQ(small.rc, 2);
    EXPECT_NE(small.log.find("does not cover one generation"), std::string::npos) << small.log;
    fs::remove_all(dir);
}

} // namespace
} // namespace cic
