// The gait experiment end to end with the real binary: the same bytes for 1 or
// 2 workers, a resume that continues bit for bit, replay commands that work on
// its runs, and a checkpoint of another kind refused before a folder exists.
#include <gtest/gtest.h>

#include <regex>

#include <chrono>
#include <csignal>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

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
    for (const std::string opt : {"cmaes", "xnes", "sade", "sepcmaes"}) {
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
    for (const std::string opt : {"cmaes", "sepcmaes"}) {
        const RunResult whole = run_settings(dir, opt + "whole", gait_settings(opt, 42, 2));
        const RunResult first = run_settings(dir, opt + "first", gait_settings(opt, 21, 2));
        ASSERT_EQ(whole.rc, 0) << whole.log;
        ASSERT_EQ(first.rc, 0) << first.log;
        const RunResult rest = run_settings(
            dir, opt + "rest",
            gait_settings(opt, 42, 1,
                          "<populationXmlLoadFrom>" + (first.run / "population.xml").string() + "</populationXmlLoadFrom>"));
        ASSERT_EQ(rest.rc, 0) << rest.log;
        EXPECT_EQ(read_text(rest.run / "population.xml"), read_text(whole.run / "population.xml")) << opt;
    }
    fs::remove_all(dir);
}

// IPOP with a tolerance no start can beat (10 m over 2 generations): every
// start restarts after its third generation, so the schedule is known:
// generations 0-2 of 7 candidates (21 evaluations), 3-5 of 14 (63), 6-8 of 28
// (147).
std::string ipop_settings(int evaluations, int workers, const std::string& gait = "", const std::string& extra = "") {
    std::string s = gait_settings("cmaes", evaluations, workers, extra);
    s.replace(s.find("</Gait>"), 0,
              "<restarts>ipop</restarts><restartPatience>2</restartPatience><restartTolerance>10</restartTolerance>" +
                  gait);
    return s;
}

TEST(GaitRun, IpopRestartsDoubleThePopulationWithinTheBudget) {
    const auto dir = temp_dir("gait-ipop");
    const RunResult one = run_settings(dir, "one", ipop_settings(146, 1));
    const RunResult two = run_settings(dir, "two", ipop_settings(146, 2));
    ASSERT_EQ(one.rc, 0) << one.log;
    ASSERT_EQ(two.rc, 0) << two.log;
    EXPECT_EQ(read_text(one.run / "population.xml"), read_text(two.run / "population.xml"));
    // 147 evaluations would finish generation 8: a budget of 146 stops before the third start's last generation.
    const std::string summary = read_text(one.run / "summary.txt");
    EXPECT_NE(summary.find("stopped: evaluation budget at generation 7"), std::string::npos) << summary;
    EXPECT_NE(summary.find("evaluations: 119\n"), std::string::npos) << summary;
    EXPECT_NE(summary.find("restarts: 2 (population 28)"), std::string::npos) << summary;
    const std::string log = read_text(one.run / "run.log");
    EXPECT_NE(log.find("restart 1: population 14 from generation 3, after 2 generations without improvement"),
              std::string::npos)
        << log;
    EXPECT_NE(log.find("restart 2: population 28 from generation 6"), std::string::npos) << log;
    const std::string pop = read_text(one.run / "population.xml");
    EXPECT_NE(pop.find("<restarts count=\"2\" populationSize=\"28\" generations=\"3 6\"/>"), std::string::npos)
        << pop;
    EXPECT_NE(read_text(one.run / "stats.csv").find("\n7,"), std::string::npos);
    // Without restarts the same settings write no <restarts> and keep 7 candidates.
    const RunResult none = run_settings(dir, "none", gait_settings("cmaes", 146, 1));
    ASSERT_EQ(none.rc, 0) << none.log;
    EXPECT_EQ(read_text(none.run / "population.xml").find("<restarts"), std::string::npos);
    EXPECT_EQ(read_text(none.run / "summary.txt").find("restarts:"), std::string::npos);
    // sade cannot restart: refused before a folder exists.
    std::string sade = ipop_settings(146, 1);
    sade.replace(sade.find("cmaes"), 5, "sade");
    const RunResult bad = run_settings(dir, "bad", sade);
    EXPECT_EQ(bad.rc, 2);
    EXPECT_NE(bad.log.find("<Gait> restarts = \"ipop\", <Gait> optimizer = \"sade\""), std::string::npos) << bad.log;
    EXPECT_FALSE(fs::exists(dir / "bad"));
    fs::remove_all(dir);
}

// A run stopped with a restart pending (after generation 2: 21 evaluations)
// or just after one (generation 3: 35), resumed, ends with the bytes of the
// uninterrupted run; a checkpoint with restarts resumed under other restart
// settings is refused.
TEST(GaitRun, IpopResumeAcrossARestartContinuesBitForBit) {
    const auto dir = temp_dir("gait-ipop-resume");
    const RunResult whole = run_settings(dir, "whole", ipop_settings(119, 2));
    ASSERT_EQ(whole.rc, 0) << whole.log;
    for (const int first_budget : {21, 35}) {
        const std::string tag = std::to_string(first_budget);
        const RunResult first = run_settings(dir, "first" + tag, ipop_settings(first_budget, 2));
        ASSERT_EQ(first.rc, 0) << first.log;
        const std::string from =
            "<populationXmlLoadFrom>" + (first.run / "population.xml").string() + "</populationXmlLoadFrom>";
        const RunResult rest = run_settings(dir, "rest" + tag, ipop_settings(119, 1, "", from));
        ASSERT_EQ(rest.rc, 0) << rest.log;
        EXPECT_EQ(read_text(rest.run / "population.xml"), read_text(whole.run / "population.xml")) << first_budget;
        EXPECT_NE(read_text(rest.run / "run.log").find(first_budget == 21 ? "restart 1: population 14"
                                                                          : "restart 2: population 28"),
                  std::string::npos)
            << read_text(rest.run / "run.log");
    }
    const std::string from =
        "<populationXmlLoadFrom>" + (whole.run / "population.xml").string() + "</populationXmlLoadFrom>";
    const RunResult other = run_settings(dir, "other", ipop_settings(200, 1, "<restartTolX>0.9</restartTolX>", from));
    EXPECT_EQ(other.rc, 2);
    EXPECT_NE(other.log.find("populationXmlLoadFrom"), std::string::npos) << other.log;
    EXPECT_FALSE(fs::exists(dir / "other"));
    const RunResult none = run_settings(dir, "none", gait_settings("cmaes", 200, 1, from));
    EXPECT_EQ(none.rc, 2);
    EXPECT_NE(none.log.find("does not replay"), std::string::npos) << none.log;
    fs::remove_all(dir);
}

// An IPOP run with two workers killed with SIGKILL at fixed fractions of its
// run time (before, around and after its restarts) and resumed from its last
// checkpoint, or started again, ends with the bytes of the run never killed.
TEST(GaitRun, IpopKilledAndResumedGivesTheSameBytes) {
    const auto dir = temp_dir("gait-ipop-kill");
    write_text(dir / "run.xml", ipop_settings(119, 2));
    const auto t0 = std::chrono::steady_clock::now();
    const RunResult reference = run_settings(dir, "reference", read_text(dir / "run.xml"));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_EQ(reference.rc, 0) << reference.log;
    const std::string want = read_text(reference.run / "population.xml");
    int resumed_from_checkpoint = 0;
    for (const double fraction : {0.15, 0.3, 0.45, 0.6, 0.75, 0.9}) {
        SCOPED_TRACE("killed after " + std::to_string(fraction * seconds) + " s of a " + std::to_string(seconds) +
                     " s run");
        const fs::path out = dir / ("killed-" + std::to_string(fraction));
        const pid_t pid = start_cic(dir / "run.xml", out, dir / "killed.log", "");
        ASSERT_GT(pid, 0);
        std::this_thread::sleep_for(std::chrono::duration<double>(fraction * seconds));
        kill(-pid, SIGKILL);   // cic and its workers
        int status = 0;
        waitpid(pid, &status, 0);
        if (!WIFSIGNALED(status)) {   // it finished before the signal (a loaded machine): nothing to resume
            ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(dir / "killed.log");
            EXPECT_EQ(read_text(only_run(out) / "population.xml"), want);
            continue;
        }
        fs::path checkpoint;
        if (fs::exists(out) && !only_run(out).empty() && fs::exists(only_run(out) / "population.xml"))
            checkpoint = only_run(out) / "population.xml";
        if (!checkpoint.empty()) ++resumed_from_checkpoint;
        const fs::path resumed = dir / ("resumed-" + std::to_string(fraction));
        const pid_t again = start_cic(dir / "run.xml", resumed, dir / "resumed.log",
                                      checkpoint.empty() ? "" : "Control.populationXmlLoadFrom=" + checkpoint.string());
        waitpid(again, &status, 0);
        ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(dir / "resumed.log");
        // Killed after its last checkpoint: the resume has no generation left to run (and writes none).
        const fs::path final_file = fs::exists(only_run(resumed) / "population.xml") ? only_run(resumed) / "population.xml"
                                                                                    : checkpoint;
        EXPECT_EQ(read_text(final_file), want)
            << (checkpoint.empty() ? "started again" : "resumed from " + checkpoint.string());
    }
    EXPECT_GT(resumed_from_checkpoint, 0) << "no kill left a checkpoint";
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
    // Eq. 7.1 split into its terms, one verdict, and a duty factor per foot (four legs).
    const std::string assess = read_text(dir / "assess.log");
    EXPECT_NE(assess.find("raw_fitness,distance,elevation,verdict,duty_factors\n"), std::string::npos) << assess;
    const std::string foot = "leg[-+]x[-+]y\\.[0-9]:[01]\\.[0-9]{3}";   // the end module of each of the four legs
    EXPECT_TRUE(std::regex_search(
        assess, std::regex(",(walking|standing up|sliding|shaking|flipped)," + foot + " " + foot + " " + foot + " " + foot + "\n")))
        << assess;
    // summary.txt splits the champion's score the same way.
    const std::regex terms("\nbest, eq. 7.1: distance ([-0-9.]+) m \\+ elevation ([-0-9.]+) m\n");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(summary, m, terms)) << summary;
    EXPECT_NEAR(std::stod(m[1]) + std::stod(m[2]), std::stod(stored), 1e-3);
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
    EXPECT_NE(bad.log.find("not a gait checkpoint: the root element is <population>"), std::string::npos) << bad.log;
    EXPECT_FALSE(fs::exists(dir / "bad"));
    const RunResult small = run_settings(dir, "small", gait_settings("cmaes", 5, 1));
    EXPECT_EQ(small.rc, 2);
    EXPECT_NE(small.log.find("does not cover one generation"), std::string::npos) << small.log;
    fs::remove_all(dir);
}

} // namespace
} // namespace cic
