// Symbolic regression end to end through the real binary: thread count does not
// change the population, resume is exact, Ctrl-C leaves a checkpoint, and bad
// population files are refused without writing anything.
#include <gtest/gtest.h>

#include <csignal>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include "support/run_helpers.hpp"

namespace cic {
namespace {

using namespace cic::testing;
namespace fs = std::filesystem;

std::string settings(int generations, int workers, const std::string& control_extra = "") {
    return R"(<settings>
  <Experiment><type>symreg</type><seed>11</seed><workers>)" + std::to_string(workers) + R"(</workers></Experiment>
  <GP><generatedPopulationSize>200</generatedPopulationSize><terminalVariableCount>1</terminalVariableCount>
      <functions>add sub mul div sin cos</functions><tournament_size>5</tournament_size>
</GP>
  <BloatControl><bloatControlVariant>1</bloatControlVariant></BloatControl>
  <Control><maximumIterations>)" + std::to_string(generations) + "</maximumIterations><minimumFitness>inf</minimumFitness>" +
           control_extra + R"(</Control>
  <SymbolicRegression><target>nguyen-7</target></SymbolicRegression>
</settings>
)";
}

TEST(SymregRun, ThreadCountDoesNotChangeThePopulation) {
    const auto dir = temp_dir("sr-threads");
    const auto one = run_settings(dir, "one", settings(8, 1));
    const auto two = run_settings(dir, "two", settings(8, 2));
    ASSERT_EQ(one.rc, 0) << one.log;
    ASSERT_EQ(two.rc, 0) << two.log;
    EXPECT_EQ(read_text(one.run / "population.xml"), read_text(two.run / "population.xml"));
    fs::remove_all(dir);
}

TEST(SymregRun, ResumeIsExact) {
    const auto dir = temp_dir("sr-resume");
    const auto full = run_settings(dir, "full", settings(10, 1));
    const auto part = run_settings(dir, "part", settings(4, 1));
    ASSERT_EQ(full.rc, 0) << full.log;
    ASSERT_EQ(part.rc, 0) << part.log;
    const auto resumed = run_settings(dir, "resumed", settings(10, 2, "<populationXmlLoadFrom>" +
                                                                  (part.run / "population.xml").string() +
                                                                  "</populationXmlLoadFrom>"));
    ASSERT_EQ(resumed.rc, 0) << resumed.log;
    EXPECT_EQ(read_text(resumed.run / "population.xml"), read_text(full.run / "population.xml"));
    fs::remove_all(dir);
}

TEST(SymregRun, CorruptPopulationIsRefusedAndNothingIsWritten) {
    const auto dir = temp_dir("sr-corrupt");
    const auto part = run_settings(dir, "part", settings(2, 1));
    ASSERT_EQ(part.rc, 0) << part.log;
    std::string text = read_text(part.run / "population.xml");
    write_text(dir / "cut.xml", text.substr(0, text.size() / 2));
    const auto bad = run_settings(dir, "bad", settings(4, 1, "<populationXmlLoadFrom>" + (dir / "cut.xml").string() +
                                                        "</populationXmlLoadFrom>"));
    EXPECT_EQ(bad.rc, 2) << bad.log;
    EXPECT_NE(bad.log.find("cut.xml:"), std::string::npos) << bad.log;
    // The original file is untouched.
    EXPECT_EQ(read_text(part.run / "population.xml"), text);
    // Another experiment's shape is refused too.
    auto other = settings(4, 1, "<populationXmlLoadFrom>" + (part.run / "population.xml").string() +
                                    "</populationXmlLoadFrom>");
    other.replace(other.find("<terminalVariableCount>1"), 24, "<terminalVariableCount>2");
    const auto foreign = run_settings(dir, "foreign", other);
    EXPECT_EQ(foreign.rc, 2) << foreign.log;
    EXPECT_NE(foreign.log.find("terminalVariableCount"), std::string::npos) << foreign.log;
    fs::remove_all(dir);
}

// Ctrl-C, or the SIGTERM a batch scheduler sends before it kills a job: the
// generation under way finishes, the checkpoint is written, and cic exits with
// 128 + the signal number.
void interrupt_writes_a_checkpoint(int sig, int expected_rc) {
    const auto dir = temp_dir("sr-signal-" + std::to_string(sig));
    // Big enough that it is still running when the signal arrives.
    write_text(dir / "long.xml", settings(100000, 1));
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        const std::string out = (dir / "out").string(), log = (dir / "long.log").string();
        const std::string cfg = (dir / "long.xml").string();
        freopen(log.c_str(), "w", stdout);
        freopen(log.c_str(), "a", stderr);
        const std::string bin = cic_binary();
        execl(bin.c_str(), bin.c_str(), "--quiet", "--settings", cfg.c_str(), "--output", out.c_str(),
              static_cast<char*>(nullptr));
        _exit(127);
    }
    // Wait for the first checkpoint, then send the signal.
    fs::path population;
    int status = 0;
    for (int i = 0; i < 600 && population.empty(); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        ASSERT_EQ(waitpid(pid, &status, WNOHANG), 0) << "cic ended early:\n" << read_text(dir / "long.log");
        if (fs::exists(dir / "out")) {
            const auto run_dir = only_run(dir / "out");
            if (!run_dir.empty() && fs::exists(run_dir / "population.xml")) population = run_dir / "population.xml";
        }
    }
    ASSERT_FALSE(population.empty()) << read_text(dir / "long.log");
    kill(pid, sig);
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << read_text(dir / "long.log");
    EXPECT_EQ(WEXITSTATUS(status), expected_rc) << read_text(dir / "long.log");
    EXPECT_NE(read_text(dir / "long.log").find(std::string("interrupted by ") + (sig == SIGTERM ? "SIGTERM" : "SIGINT")),
              std::string::npos);
    // The exact command that goes on.
    EXPECT_NE(read_text(dir / "long.log").find("; continue with: cic resume " + population.parent_path().string()),
              std::string::npos)
        << read_text(dir / "long.log");
    const std::string text = read_text(population);
    EXPECT_NE(text.find("</population>"), std::string::npos);   // complete, not half-written
    EXPECT_TRUE(fs::exists(population.parent_path() / "summary.txt"));
    fs::remove_all(dir);
}

TEST(SymregRun, InterruptWritesACheckpointThenExits) { interrupt_writes_a_checkpoint(SIGINT, 130); }

TEST(SymregRun, SigtermWritesACheckpointThenExits) { interrupt_writes_a_checkpoint(SIGTERM, 143); }

} // namespace
} // namespace cic
