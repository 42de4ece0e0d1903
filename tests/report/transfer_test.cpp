// A run's best genotype on other robots (report/transfer.hpp): the tiling and
// interpolation rules joint by joint, bad pairs of robots refused, and the
// replays: on its own robot a genotype gives its stored fitness, on another
// the bits of an evaluation made there directly.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "cic/core/error.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/robot_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/report/transfer.hpp"
#include "cic/sim/centipede.hpp"
#include "support/files.hpp"
#include "support/run_helpers.hpp"

namespace fs = std::filesystem;
using namespace cic;

namespace {

std::string name_of(const sim::RobotSpec& r, std::size_t joint) {
    return r.modules[static_cast<std::size_t>(r.actuated()[joint])].name;
}

std::size_t joint_named(const sim::RobotSpec& r, const std::string& name) {
    for (std::size_t j = 0; j < r.actuated().size(); ++j)
        if (name_of(r, j) == name) return j;
    ADD_FAILURE() << "no joint " << name << " in " << r.name;
    return 0;
}

fs::path robot_file(const std::string& name) { return fs::path(CIC_SOURCE_DIR) / "settings" / "robots" / name; }

} // namespace

// Row k of the bigger body copies row k mod 2 of centipede-2, hinge by hinge.
TEST(TransferTiling, RepeatsTheSourceRowsAlongTheBody) {
    const auto small = sim::centipede(2, false), big = sim::centipede(5, false);
    const auto map = report::tile_joints(small, big);
    ASSERT_EQ(map.size(), big.actuated().size());
    for (std::size_t j = 0; j < map.size(); ++j) {
        const std::string target = name_of(big, j), source = name_of(small, map[j]);
        // "pairK+x.S": the same side and segment, pair K mod 2.
        const int k = std::stoi(target.substr(4, target.find_first_of("+-") - 4));
        EXPECT_EQ(source, "pair" + std::to_string(k % 2) + target.substr(target.find_first_of("+-"))) << target;
    }
}

// On the same body tiling is the identity.
TEST(TransferTiling, IsTheIdentityOnTheSameRobot) {
    const auto r = sim::centipede(4, true);
    const auto map = report::tile_joints(r, r);
    for (std::size_t j = 0; j < map.size(); ++j) EXPECT_EQ(map[j], j);
}

// An irregular twin's shortened leg lacks its tip hinge: a regular target's
// tip takes it from the nearest source row that has one.
TEST(TransferTiling, TakesAMissingHingeFromTheNearestRow) {
    const auto small = sim::centipede(2, true), big = sim::centipede(4, false);
    const auto map = report::tile_joints(small, big);
    // centipede-2-irregular's front pair (pair1) has a two-module -x leg.
    EXPECT_EQ(name_of(small, map[joint_named(big, "pair1-x.2")]), "pair0-x.2");
    EXPECT_EQ(name_of(small, map[joint_named(big, "pair3-x.2")]), "pair0-x.2");
    EXPECT_EQ(name_of(small, map[joint_named(big, "pair3-x.1")]), "pair1-x.1");
}

// A hinge with no counterpart anywhere (R0's legs stand elsewhere across its body) is refused, naming it.
TEST(TransferTiling, RefusesAHingeWithNoCounterpart) {
    const auto r0 = sim::preset(0, false), big = sim::centipede(2, false);
    try {
        report::tile_joints(r0, big);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("no counterpart"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("target joint pair0+x.0"), std::string::npos) << e.what();
    }
}

// Offsets are interpolated along the body: centipede-2's rows lie at -1 and 1,
// centipede-4's at -1, -1/3, 1/3 and 1.
TEST(TransferInterpolation, BlendsTheTwoNearestRows) {
    const auto small = sim::centipede(2, false), big = sim::centipede(4, false);
    const auto blend = report::interpolate_joints(small, big);
    const double want[] = {0.0, 1.0 / 3, 2.0 / 3, 1.0};
    for (int k = 0; k < 4; ++k) {
        const auto& b = blend[joint_named(big, "pair" + std::to_string(k) + "+x.1")];
        const double value_at_front = b.a == b.b ? (name_of(small, b.a) == "pair1+x.1" ? 1.0 : 0.0) : b.weight_b;
        EXPECT_NEAR(value_at_front, want[k], 1e-15) << "pair " << k;
        EXPECT_EQ(name_of(small, b.a).substr(5), "+x.1");
        EXPECT_EQ(name_of(small, b.b).substr(5), "+x.1");
    }
    // The same robot: each hinge its own value.
    const auto same = report::interpolate_joints(big, big);
    for (std::size_t j = 0; j < same.size(); ++j) {
        const double w = same[j].weight_b;
        EXPECT_TRUE((same[j].a == j && w == 0.0) || (same[j].b == j && w == 1.0)) << j;
    }
}

class TransferReplay : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("cic-transfer-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    // A short run on centipede-2 of a shipped settings file.
    fs::path run(const std::string& settings, const std::string& extra) {
        const std::string cmd = "--quiet --settings " + (fs::path(CIC_SOURCE_DIR) / "settings" / settings).string() +
                                " --set Simulator.robotFile=" + robot_file("centipede-2.xml").string() +
                                " --set Experiment.workers=1 --seed 5 --output " + (dir / "out").string() + " " + extra;
        EXPECT_EQ(cic::testing::run_command(cmd, dir / "log.txt"), 0) << cic::testing::read_text(dir / "log.txt");
        return cic::testing::only_run(dir / "out");
    }
    fs::path dir;
};

// HyperGP trees: on their own robot the stored fitness, on centipede-4 the bits
// of the same trees evaluated there directly.
TEST_F(TransferReplay, TreesGiveTheirOwnFitnessAndTheTargetsBits) {
    const fs::path r = run("r1_switch_hybrid.xml", "--set Neural.switchPatience=0 --set Neural.switchShare=0 "
                                                   "--set Control.maximumIterations=2 --set GP.generatedPopulationSize=8");
    const report::TransferSource src = report::read_transfer_source(r.string());
    ASSERT_FALSE(src.trees.empty());
    report::TransferTarget own{src.robot, src.robot_file};
    const auto home = report::replay_transferred(src, own, report::OffsetRule::Interpolate, 0, false);
    EXPECT_EQ(home.replayed_fitness, src.stored_fitness);

    report::TransferTarget big{io::read_robot_file(robot_file("centipede-4.xml")),
                               robot_file("centipede-4.xml").string()};
    std::string how;
    const auto there = report::replay_transferred(src, big, report::OffsetRule::Interpolate, 0, false, &how);
    EXPECT_EQ(how, "unchanged");
    io::Settings s = src.settings;
    s.robot.robot_file = big.file;
    const hypergp::Outcome direct = hypergp::run(hypergp::Model::from_settings(s), src.trees);
    EXPECT_EQ(there.replayed_fitness, direct.fitness);
    EXPECT_NE(there.replayed_fitness, home.replayed_fitness);
}

// A direct gait: its own fitness at home; tiled onto centipede-4 (rows 0 1 0 1).
TEST_F(TransferReplay, DirectGaitIsTiled) {
    const fs::path r = run("r1_gait_ipop.xml", "--set Gait.evaluations=24");
    const report::TransferSource src = report::read_transfer_source(r.string());
    ASSERT_TRUE(src.trees.empty());
    report::TransferTarget own{src.robot, src.robot_file};
    EXPECT_EQ(report::replay_transferred(src, own, report::OffsetRule::None, 0, false).replayed_fitness,
              src.stored_fitness);
    report::TransferTarget big{io::read_robot_file(robot_file("centipede-4.xml")),
                               robot_file("centipede-4.xml").string()};
    std::string how;
    const auto there = report::replay_transferred(src, big, report::OffsetRule::None, 0, false, &how);
    EXPECT_EQ(how, "tiled");
    // The same tiled vector, by hand, replayed there.
    io::Settings s = src.settings;
    s.robot.robot_file = big.file;
    std::vector<double> x{src.gait[0]};
    for (int pair = 0; pair < 4; ++pair)
        for (std::size_t j = 0; j < src.robot.actuated().size(); ++j) {
            const std::string n = name_of(src.robot, j);
            if (std::stoi(n.substr(4, 1)) != pair % 2) continue;
            x.insert(x.end(), src.gait.begin() + static_cast<long>(1 + 3 * j), src.gait.begin() + static_cast<long>(4 + 3 * j));
        }
    EXPECT_EQ(report::replay_gait_vector(s, x, 0, false).replayed_fitness, there.replayed_fitness);
}

// Offset-HybrID: "none" drops the offsets (the trees alone), "interpolate" carries them.
TEST_F(TransferReplay, OffsetsFollowTheStatedRule) {
    const fs::path r = run("r1_offset_hybrid.xml", "--set Control.maximumIterations=2 --set GP.generatedPopulationSize=8");
    const report::TransferSource src = report::read_transfer_source(r.string());
    ASSERT_EQ(src.offsets.size(), src.robot.actuated().size());
    report::TransferTarget big{io::read_robot_file(robot_file("centipede-4.xml")),
                               robot_file("centipede-4.xml").string()};
    std::string how;
    const auto dropped = report::replay_transferred(src, big, report::OffsetRule::None, 0, false, &how);
    EXPECT_EQ(how, "offsets-dropped");
    io::Settings s = src.settings;
    s.robot.robot_file = big.file;
    s.neural.direct_offsets = false;
    EXPECT_EQ(dropped.replayed_fitness, hypergp::run(hypergp::Model::from_settings(s), src.trees).fitness);

    const auto carried = report::replay_transferred(src, big, report::OffsetRule::Interpolate, 0, false, &how);
    EXPECT_EQ(how, "offsets-interpolated");
    s.neural.direct_offsets = true;
    std::vector<double> offsets;
    for (const auto& b : report::interpolate_joints(src.robot, big.robot))
        offsets.push_back((1 - b.weight_b) * src.offsets[b.a] + b.weight_b * src.offsets[b.b]);
    EXPECT_EQ(carried.replayed_fitness, hypergp::run(hypergp::Model::from_settings(s), src.trees, offsets).fitness);
}

// `cic transfer`: bad input exits 2 naming what is wrong; a run gives one row per robot, its own first.
TEST_F(TransferReplay, CommandRefusesBadInputAndWritesOneRowPerRobot) {
    const fs::path r = run("r1_gait_ipop.xml", "--set Gait.evaluations=24");
    const fs::path log = dir / "transfer.txt";
    EXPECT_EQ(cic::testing::run_command("transfer " + r.string() + " --robot centipede-99", log), 2);
    EXPECT_NE(cic::testing::read_text(log).find("centipede-99"), std::string::npos) << cic::testing::read_text(log);
    EXPECT_EQ(cic::testing::run_command("transfer " + r.string() + " --robot R1 --offsets stretch", log), 2);
    EXPECT_NE(cic::testing::read_text(log).find("interpolate, none"), std::string::npos) << cic::testing::read_text(log);
    EXPECT_EQ(cic::testing::run_command("transfer " + (dir / "nothing").string() + " --robot R1", log), 2);

    ASSERT_EQ(cic::testing::run_command("--quiet transfer " + r.string() + " --robot centipede-4 --robot R1 --out " +
                                       (dir / "t.csv").string(),
                                   log),
              0)
        << cic::testing::read_text(log);
    const std::string csv = cic::testing::read_text(dir / "t.csv");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4) << csv;
    EXPECT_NE(csv.find(",centipede-2,12,own,"), std::string::npos) << csv;
    EXPECT_NE(csv.find(",centipede-4,24,tiled,"), std::string::npos) << csv;
    EXPECT_NE(csv.find(",R1,12,tiled,"), std::string::npos) << csv;
}

// Switch-HybrID past its hand-over: the genotype transferred is its HyperGP
// phase's best (trees), not the direct gait it went on with.
TEST_F(TransferReplay, SwitchHybridGivesItsHyperGpPhasesTrees) {
    const fs::path r = run("r1_switch_hybrid.xml", "--set Gait.evaluations=48 --set GP.generatedPopulationSize=8 "
                                                   "--set Neural.switchShare=0.3");
    ASSERT_TRUE(io::is_gait_file(r / "population.xml")) << "the run did not hand over";
    const report::TransferSource src = report::read_transfer_source(r.string());
    EXPECT_FALSE(src.trees.empty());
    EXPECT_NE(src.what.find("Switch-HybrID's HyperGP phase"), std::string::npos) << src.what;
    // The gait it went on with is what the run's latest genotype is.
    EXPECT_TRUE(report::read_run_genotype(r.string(), report::SwitchPhase::Latest).trees.empty());
    report::TransferTarget own{src.robot, src.robot_file};
    EXPECT_EQ(report::replay_transferred(src, own, report::OffsetRule::None, 0, false).replayed_fitness,
              src.stored_fitness);
}

// A genotype evolved on several bodies walks the target alone: not the mean
// with the run's other body.
TEST_F(TransferReplay, SeveralBodiesRunWalksTheTargetAlone) {
    const fs::path r = run("r1_switch_hybrid.xml", "--set Neural.switchPatience=0 --set Neural.switchShare=0 "
                                                   "--set Control.maximumIterations=2 --set GP.generatedPopulationSize=6 "
                                                   "--set Simulator.extraRobotFiles=" +
                                                       robot_file("centipede-4.xml").string());
    const report::TransferSource src = report::read_transfer_source(r.string());
    report::TransferTarget big{io::read_robot_file(robot_file("centipede-8.xml")),
                               robot_file("centipede-8.xml").string()};
    const auto there = report::replay_transferred(src, big, report::OffsetRule::None, 0, false);
    io::Settings s = src.settings;
    s.robot.robot_file = big.file;
    s.robot.extra_robot_files.clear();
    EXPECT_EQ(there.replayed_fitness, hypergp::run(hypergp::Model::from_settings(s), src.trees).fitness);
}
