// A settings file of thesis table B.1 and nothing else (no <Experiment>
// section) runs the HyperGP experiment on its robot_type, with the thesis's values.
#include <gtest/gtest.h>

#include "cic/io/settings_io.hpp"
#include "cic/io/settings_table.hpp"
#include "support/run_helpers.hpp"

namespace cic {
namespace {

using namespace cic::testing;
namespace fs = std::filesystem;

const fs::path kTableB1 = fs::path(CIC_SOURCE_DIR) / "tests" / "data" / "table_b1_settings.xml";

TEST(TableB1, ReadsAsHyperGpWithTheThesisValues) {
    const io::Settings s = io::read_settings(kTableB1);
    EXPECT_EQ(s.experiment.type, "hypergp");
    EXPECT_EQ(s.robot.robot_type, 1);
    // Every value the table gives is also cic's default: nothing else is needed.
    const io::Settings defaults;
    for (const auto& k : io::settings_table()) {
        if (k.section != "Experiment") {
            EXPECT_EQ(k.get(s), k.get(defaults)) << "<" << k.section << "> " << k.key;
        }
    }
    // A symbolic-regression file without a type is still symbolic regression.
    const io::Settings sr = io::read_settings_string(
        "<settings><SymbolicRegression><target>koza-1</target></SymbolicRegression></settings>", "sr.xml");
    EXPECT_EQ(sr.experiment.type, "symreg");
}

TEST(TableB1, RunsHyperGpOnR1) {
    const auto dir = temp_dir("table-b1");
    // The table's file with only a shorter run: 6 individuals, 2 generations, 3 s.
    const int rc = run_command("--quiet --settings " + kTableB1.string() + " --output " + (dir / "out").string() +
                                   " --set GP.generatedPopulationSize=6 --set Control.maximumIterations=2"
                                   " --set Simulator.sample_to=3",
                               dir / "log");
    const std::string log = read_text(dir / "log");
    ASSERT_EQ(rc, 0) << log;
    const fs::path run = only_run(dir / "out");
    const std::string summary = read_text(run / "summary.txt");
    EXPECT_NE(summary.find("robot R1"), std::string::npos) << summary;
    EXPECT_NE(read_text(run / "settings.xml").find("<type>hypergp</type>"), std::string::npos);
    fs::remove_all(dir);
}

} // namespace
} // namespace cic
