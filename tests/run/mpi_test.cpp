// `mpirun -np N cic` end to end (docs/mpi.md): HyperGP on MPI ranks gives the
// same population bytes as one worker, the worker ranks write nothing, bad input
// ends every rank with exit code 2, and a plain run never initialises MPI.
#ifdef CIC_HAVE_MPI

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include "support/child_env.hpp"
#include "support/run_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using cic::testing::cic_binary;
using cic::testing::read_text;
using cic::testing::tiny_hypergp_settings;

bool have_mpirun() { return std::system("command -v mpirun > /dev/null 2>&1") == 0; }

// Open MPI on a fresh machine or container, as root, without network: local
// launch only (no ssh), shared memory between ranks, no cross-memory attach
// (often forbidden in containers), and the right to run as root.
const std::string kMpirun =
    cic::testing::without_leak_check() +
    "env OMPI_MCA_plm=isolated OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none "
    "OMPI_MCA_rmaps_base_oversubscribe=1 timeout 120 mpirun --allow-run-as-root --oversubscribe ";

// A plain run outside any launcher: launcher variables removed.
const std::string kPlain = "env -u OMPI_COMM_WORLD_SIZE -u PMI_SIZE -u PMIX_RANK ";

class Mpi : public ::testing::Test {
protected:
    void SetUp() override {
        if (!have_mpirun()) GTEST_SKIP() << "mpirun is not on PATH";
        dir = fs::temp_directory_path() /
              ("cic-mpi-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override {
        if (!dir.empty()) fs::remove_all(dir);
    }

    fs::path write(const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return dir / name;
    }

    // Runs `prefix cic args`; returns the exit code, output in dir/name.log.
    int run(const std::string& name, const std::string& prefix, const std::string& args) {
        const std::string cmd =
            prefix + "'" + cic_binary() + "' " + args + " > '" + (dir / (name + ".log")).string() + "' 2>&1";
        const int rc = std::system(cmd.c_str());
        return WIFEXITED(rc) ? WEXITSTATUS(rc) : 128;
    }
    std::string log(const std::string& name) { return read_text(dir / (name + ".log")); }

    // The single run folder below dir/name; fails the test if there is not exactly one.
    fs::path only_run(const std::string& name) {
        std::vector<fs::path> found;
        for (const auto& e : fs::directory_iterator(dir / name)) found.push_back(e.path());
        EXPECT_EQ(found.size(), 1u) << "worker ranks must not create run folders";
        return found.empty() ? fs::path() : found.front();
    }

    std::string job(const fs::path& settings, const std::string& output) {
        return "--quiet --settings '" + settings.string() + "' --output '" + (dir / output).string() + "'";
    }

    fs::path dir;
};

TEST_F(Mpi, ThreeRanksGiveTheSamePopulationAsOneWorker) {
    const auto settings = write("tiny.xml", tiny_hypergp_settings(3, 1));
    ASSERT_EQ(run("one", kPlain, job(settings, "one")), 0) << log("one");
    ASSERT_EQ(run("mpi", kMpirun + "-np 3 ", job(settings, "mpi")), 0) << log("mpi");
    const fs::path one = only_run("one"), mpi = only_run("mpi");
    EXPECT_EQ(read_text(one / "population.xml"), read_text(mpi / "population.xml"));
    EXPECT_EQ(read_text(one / "stats.csv").size(), read_text(mpi / "stats.csv").size());
    EXPECT_NE(read_text(mpi / "run.log").find("MPI: 3 ranks, evaluation on ranks 1..2"), std::string::npos)
        << read_text(mpi / "run.log");
    EXPECT_EQ(read_text(one / "run.log").find("MPI"), std::string::npos);
}

// The golden run with forced physics failures: 3 ranks give the bytes that 1
// and 2 worker processes give (tests/experiments/golden_test.cpp).
TEST_F(Mpi, ThreeRanksGiveTheGoldenHash) {
    const auto settings = write("golden.xml", cic::testing::golden_hypergp_settings(1));
    ASSERT_EQ(run("mpi", kMpirun + "-np 3 ", job(settings, "mpi")), 0) << log("mpi");
    EXPECT_EQ(cic::testing::file_hash(only_run("mpi") / "population.xml"), cic::testing::kGoldenHypergp);
}

// The golden MAP-Elites run: the archive's batches on 3 ranks give the bytes
// of 1 and 2 worker processes.
TEST_F(Mpi, ThreeRanksGiveTheGoldenMapElitesHash) {
    const auto settings = write("me.xml", cic::testing::golden_me_hypergp_settings(1));
    ASSERT_EQ(run("mpi", kMpirun + "-np 3 ", job(settings, "mpi")), 0) << log("mpi");
    EXPECT_EQ(cic::testing::file_hash(only_run("mpi") / "population.xml"), cic::testing::kGoldenMapElitesHypergp);
}

// Switch-HybrID through the one run loop on 3 ranks: both phases (HyperGP's
// trees, then CMA-ES's gait vectors) go to the worker ranks, and the run ends in
// the bytes of one worker process.
TEST_F(Mpi, SwitchHybridOnThreeRanksGivesTheBytesOfOneWorker) {
    const fs::path settings = fs::path(CIC_SOURCE_DIR) / "settings" / "r1_switch_hybrid.xml";
    const std::string sets = " --set GP.generatedPopulationSize=6 --set Gait.evaluations=60"
                             " --set Simulator.sample_to=2 --set Simulator.delayed_start=0.5 --set Experiment.workers=1";
    ASSERT_EQ(run("one", kPlain, job(settings, "one") + sets), 0) << log("one");
    ASSERT_EQ(run("mpi", kMpirun + "-np 3 ", job(settings, "mpi") + sets), 0) << log("mpi");
    const fs::path one = only_run("one"), mpi = only_run("mpi");
    EXPECT_EQ(read_text(one / "population.xml"), read_text(mpi / "population.xml"));
    const std::string ran = read_text(mpi / "run.log");
    EXPECT_NE(ran.find("switch: HyperGP hands over"), std::string::npos) << ran;
    EXPECT_NE(ran.find("MPI: 3 ranks"), std::string::npos) << ran;
}

TEST_F(Mpi, BadSettingsEndEveryRankWithExitCode2AndWriteNothing) {
    const auto settings = write("bad.xml", "<settings><Experiment><type>bogus</type></Experiment></settings>\n");
    EXPECT_EQ(run("bad", kMpirun + "-np 3 ", job(settings, "out")), 2) << log("bad");
    EXPECT_NE(log("bad").find("bogus"), std::string::npos) << log("bad");
    EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST_F(Mpi, SymbolicRegressionUnderMpirunMatchesAPlainRun) {
    const std::string settings = std::string(CIC_SOURCE_DIR) + "/settings/symreg_deap.xml";
    const std::string args = " --set Control.maximumIterations=4";
    ASSERT_EQ(run("plain", kPlain, job(settings, "plain") + args), 0) << log("plain");
    ASSERT_EQ(run("mpi", kMpirun + "-np 2 ", job(settings, "mpi") + args), 0) << log("mpi");
    EXPECT_EQ(read_text(only_run("plain") / "population.xml"), read_text(only_run("mpi") / "population.xml"));
}

// With a transport that does not exist, MPI_Init fails: the mpirun run must
// fail (so this probe can see MPI being initialised) and the plain run, with
// the same environment, must not notice (it never initialises MPI).
TEST_F(Mpi, PlainRunNeverInitialisesMpi) {
    const auto settings = write("tiny.xml", tiny_hypergp_settings(3, 2));
    const std::string broken = "OMPI_MCA_pml=no-such-transport ";
    EXPECT_NE(run("mpi", "env " + broken + kMpirun + "-np 2 ", job(settings, "mpi")), 0) << log("mpi");
    // Two workers: the `cic worker` children inherit the environment and must keep out of MPI too.
    ASSERT_EQ(run("plain", kPlain + broken, job(settings, "plain")), 0) << log("plain");
    EXPECT_TRUE(fs::exists(only_run("plain") / "population.xml"));
}

} // namespace

#endif // CIC_HAVE_MPI
