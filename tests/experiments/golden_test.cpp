// Golden hashes: the final population files of two short, fixed-seed runs.
// A HyperGP run in which about half the evaluations fail as physics blow-ups
// gives the same bytes with 1 and 2 worker processes (and with 3 MPI ranks,
// tests/run/mpi_test.cpp); so does a HyperGP run on the CPG substrate with
// feedback; so do two MAP-Elites runs (HyperGP and gait); a symbolic-regression run gives the same bytes with 1 and 2 threads. A change that alters results must update these hashes on
// purpose and say why in its commit message.
#include <gtest/gtest.h>

#include "support/run_helpers.hpp"

namespace cic {
namespace {

using namespace cic::testing;
namespace fs = std::filesystem;

// Runs `settings(1)` and `settings(2)` (workers or threads); both final
// population files must hash to `want`. Returns the 1-worker run folder.
fs::path expect_golden(const std::string& name, std::string (*settings)(int), const std::string& want) {
    const auto dir = temp_dir("golden-" + name);
    const auto one = run_settings(dir, "one", settings(1));
    const auto two = run_settings(dir, "two", settings(2));
    EXPECT_EQ(one.rc, 0) << one.log;
    EXPECT_EQ(two.rc, 0) << two.log;
    EXPECT_EQ(file_hash(one.run / "population.xml"), want);
    EXPECT_EQ(file_hash(two.run / "population.xml"), want);
    return one.run;
}

TEST(Golden, HypergpWithPhysicsFailures) {
    const fs::path run = expect_golden("hgp", golden_hypergp_settings, kGoldenHypergp);
    EXPECT_NE(read_text(run / "populations" / "gen-0000.xml").find("key=\"failed\">physics blow-up"),
              std::string::npos)
        << "no forced failure";
    fs::remove_all(run.parent_path().parent_path());
}

TEST(Golden, HypergpCpgSubstrate) {
    const fs::path run = expect_golden("cpg", golden_cpg_settings, kGoldenCpg);
    EXPECT_NE(read_text(run / "settings.xml").find("<substrate>cpg</substrate>"), std::string::npos);
    fs::remove_all(run.parent_path().parent_path());
}

TEST(Golden, SymbolicRegression) {
    const fs::path run = expect_golden("sr", golden_symreg_settings, kGoldenSymreg);
    fs::remove_all(run.parent_path().parent_path());
}

// The golden IPOP run: CMA-ES gaits on R0 (2.5 s simulations), 7 candidates,
// restarts when a start's best rises by no more than 1 mm (the default
// tolerance) over 3 generations, 150 evaluations: at least one restart.
std::string golden_ipop_settings(int workers) {
    return R"(<settings>
  <Experiment><type>gait</type><seed>4</seed><workers>)" + std::to_string(workers) + R"(</workers></Experiment>
  <Gait><optimizer>cmaes</optimizer><evaluations>150</evaluations><populationSize>7</populationSize>
      <bounds>reflect</bounds><restarts>ipop</restarts><restartPatience>3</restartPatience></Gait>
  <Simulator><robot_type>0</robot_type><sample_to>2.5</sample_to><delayed_start>0.5</delayed_start></Simulator>
</settings>
)";
}
const std::string kGoldenIpop = "a12dd9cd8809fb02";   // golden_ipop_settings' final population.xml

TEST(Golden, GaitCmaesWithIpopRestarts) {
    const fs::path run = expect_golden("ipop", golden_ipop_settings, kGoldenIpop);
    EXPECT_NE(read_text(run / "run.log").find("restart 1: population 14"), std::string::npos) << "no restart";
    EXPECT_NE(read_text(run / "population.xml").find("<restarts count=\""), std::string::npos);
    fs::remove_all(run.parent_path().parent_path());
}

TEST(Golden, MapElitesHypergp) {
    const fs::path run = expect_golden("me-hgp", golden_me_hypergp_settings, kGoldenMapElitesHypergp);
    EXPECT_NE(read_text(run / "population.xml").find("<tree>"), std::string::npos);
    EXPECT_NE(read_text(run / "stats.csv").find(",qd_score,coverage,filled,kept\n"), std::string::npos);
    fs::remove_all(run.parent_path().parent_path());
}

TEST(Golden, MapElitesGait) {
    const fs::path run = expect_golden("me-gait", golden_me_gait_settings, kGoldenMapElitesGait);
    EXPECT_NE(read_text(run / "population.xml").find("<x>"), std::string::npos);
    fs::remove_all(run.parent_path().parent_path());
}

} // namespace
} // namespace cic
