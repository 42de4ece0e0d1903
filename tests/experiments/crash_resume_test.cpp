// Crash safety: a HyperGP run with two worker processes, killed with SIGKILL
// at random moments and resumed from its last checkpoint (or started again
// when it died before the first), ends with the same population bytes as the
// run that was never interrupted.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <random>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include "support/run_helpers.hpp"

namespace cic {
namespace {

using namespace cic::testing;
namespace fs = std::filesystem;

TEST(CrashResume, KilledAtRandomMomentsAndResumedGivesTheSameBytes) {
    const auto dir = temp_dir("crash");
    write_text(dir / "run.xml", tiny_hypergp_settings(8, 2));

    const auto t0 = std::chrono::steady_clock::now();
    const auto reference = run_settings(dir, "reference", read_text(dir / "run.xml"));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_EQ(reference.rc, 0) << reference.log;
    const std::string want = read_text(reference.run / "population.xml");

    std::mt19937 rng(20261201);   // fixed: the same moments every time the test runs
    std::uniform_real_distribution<double> moment(0.05, 0.95);
    for (int k = 0; k < 6; ++k) {
        const double at = moment(rng) * seconds;
        SCOPED_TRACE("killed after " + std::to_string(at) + " s of a " + std::to_string(seconds) + " s run");
        fs::path resumed, from;
        ASSERT_TRUE(kill_then_resume(dir, dir / "run.xml", k, at, false, resumed, from)) << read_text(dir / "resumed.log");
        EXPECT_EQ(read_text(resumed / "population.xml"), want)
            << (from.empty() ? "started again" : "resumed from " + from.string());
    }
    fs::remove_all(dir);
}

// What Slurm does before it kills a job: SIGTERM to every process of the job.
// The workers ignore it, the generation under way finishes, the checkpoint is
// written (exit 143), and a resume ends as if nothing had happened.
TEST(CrashResume, SigtermToTheWholeJobResumesExactly) {
    const auto dir = temp_dir("sigterm-group");
    write_text(dir / "run.xml", tiny_hypergp_settings(8, 2));
    const auto reference = run_settings(dir, "reference", read_text(dir / "run.xml"));
    ASSERT_EQ(reference.rc, 0) << reference.log;

    const pid_t pid = start_cic(dir / "run.xml", dir / "term", dir / "term.log", "");
    ASSERT_GT(pid, 0);
    fs::path checkpoint;   // wait for the first checkpoint, then signal the group
    for (int i = 0; i < 600 && checkpoint.empty(); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        if (fs::exists(dir / "term") && !only_run(dir / "term").empty() &&
            fs::exists(only_run(dir / "term") / "population.xml"))
            checkpoint = only_run(dir / "term") / "population.xml";
    }
    ASSERT_FALSE(checkpoint.empty()) << read_text(dir / "term.log");
    kill(-pid, SIGTERM);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << read_text(dir / "term.log");
    if (WEXITSTATUS(status) == 0) GTEST_SKIP() << "the run ended before the signal arrived";
    ASSERT_EQ(WEXITSTATUS(status), 143) << read_text(dir / "term.log");
    EXPECT_EQ(read_text(only_run(dir / "term") / "run.log").find("worker replaced"), std::string::npos)
        << "a worker died of the signal";
    const pid_t again = start_cic(dir / "run.xml", dir / "resumed", dir / "resumed.log",
                              "Control.populationXmlLoadFrom=" + checkpoint.string());
    waitpid(again, &status, 0);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(dir / "resumed.log");
    EXPECT_EQ(read_text(only_run(dir / "resumed") / "population.xml"), read_text(reference.run / "population.xml"));
    fs::remove_all(dir);
}

} // namespace
} // namespace cic
