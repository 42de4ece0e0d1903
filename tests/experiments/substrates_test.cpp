// HyperGP's CPG and gait substrates, the evolved clock and the controller
// factory (experiments/hypergp/{queries,cpg_substrate,gait_substrate,controller}),
// and the gait experiment's CPG encoding, its direct twin.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "cic/sim/cpg.hpp"
#include "cic/experiments/gait/cpg_encoding.hpp"
#include "cic/experiments/hypergp/controller.hpp"
#include "cic/experiments/hypergp/cpg_substrate.hpp"
#include "cic/experiments/hypergp/gait_substrate.hpp"
#include "cic/experiments/hypergp/neural_controller.hpp"
#include "cic/experiments/hypergp/queries.hpp"
#include "cic/experiments/hypergp/substrate_geometry.hpp"

namespace {

using cic::nn::NeuralConfig;
using cic::tree::Forest;
using cic::tree::Tree;
constexpr double kPi = std::numbers::pi;

Forest forest(std::initializer_list<const char*> trees) {
    Forest f;
    for (const char* t : trees) f.push_back(Tree::parse(t));
    return f;
}

TEST(HypergpQueries, AskAnswersEachQueryFromItsTree) {
    const Forest f = forest({"(add x0 x3)", "(mul x1 x2)"});
    const std::vector<cic::hypergp::Query> qs{{0, {1, 2}, {3, 4}}, {1, {1, 2}, {3, 4}}, {0, {-1, 0}, {0, 5}}};
    EXPECT_EQ(cic::hypergp::ask(f, NeuralConfig{}, qs), (std::vector<double>{5.0, 6.0, 4.0}));
    const std::vector<cic::hypergp::Query> bad{{2, {0, 0}, {0, 0}}};
    EXPECT_THROW(cic::hypergp::ask(f, NeuralConfig{}, bad), std::invalid_argument);
    EXPECT_THROW(cic::hypergp::ask(forest({"x5"}), NeuralConfig{}, qs), std::invalid_argument);
    EXPECT_EQ(cic::hypergp::squash(NAN), 0.0);
    EXPECT_EQ(cic::hypergp::unit(INFINITY), 1.0);
}

TEST(HypergpQueries, EvolvedFrequencyMapsTheTreeIntoTheRange) {
    NeuralConfig cfg;
    cfg.frequency_min = 0.5;
    cfg.frequency_max = 2.5;
    EXPECT_DOUBLE_EQ(cic::hypergp::evolved_frequency(forest({"0"}), cfg), 1.5);
    // Asked at (F, F) = (-1.5, -1.5, -1.5, -1.5): x0 = -1.5.
    EXPECT_DOUBLE_EQ(cic::hypergp::evolved_frequency(forest({"x0"}), cfg), 0.5 + 2.0 * 0.5 * (1 + std::tanh(-1.5)));
}

TEST(CpgSubstrate, WeightsAreTheScaledTreeAtTheJointsAndTheirPairs) {
    const auto robot = cic::sim::preset(1, false);
    const auto g = cic::hypergp::substrate_geometry(robot);
    NeuralConfig cfg;
    cfg.substrate = "cpg";
    const Forest f = forest({"(sub x0 x2)"});   // 0 on the diagonal: no own rotation
    const cic::sim::CpgSpec s = cic::hypergp::cpg_spec(robot, f, cfg, 0.0125);
    ASSERT_EQ(s.self.size(), g.joints.size());
    for (double w : s.self) EXPECT_EQ(w, 0.0);
    EXPECT_EQ(s.edges, cic::sim::cpg_neighbours(robot, 2));
    for (std::size_t k = 0; k < s.edges.size(); ++k) {
        const auto& a = g.joints[static_cast<std::size_t>(s.edges[k].a)];
        const auto& b = g.joints[static_cast<std::size_t>(s.edges[k].b)];
        EXPECT_DOUBLE_EQ(s.coupling[k], cfg.cpg_weight_scale * std::tanh(a.x - b.x));
    }
    EXPECT_TRUE(s.feedback.empty());
    cfg.cpg_feedback = 3.0;
    cfg.cpg_hops = 1;
    const cic::sim::CpgSpec fb = cic::hypergp::cpg_spec(robot, forest({"1", "x3"}), cfg, 0.0125);
    EXPECT_LT(fb.edges.size(), s.edges.size());
    ASSERT_EQ(fb.feedback.size(), g.joints.size());
    for (double v : fb.feedback) EXPECT_DOUBLE_EQ(v, 3.0 * std::tanh(-1.5));   // tree 1 at (p_i, FB): x3 = -1.5
    for (double w : fb.self) EXPECT_DOUBLE_EQ(w, cfg.cpg_weight_scale * std::tanh(1.0));
    EXPECT_THROW(cic::hypergp::cpg_spec(robot, Forest{}, cfg, 0.0125), std::invalid_argument);
}

TEST(GaitSubstrate, OneTreeTellsTheParametersApartByTheirPoint) {
    const auto robot = cic::sim::preset(1, false);
    NeuralConfig cfg;
    cfg.substrate = "gait";
    // x2 is the parameter point's x: A = -0.5, P = 0, O = 0.5.
    const cic::sim::GaitSpec s = cic::hypergp::gait_spec(robot, forest({"x2"}), cfg);
    ASSERT_EQ(s.joints.size(), robot.actuated().size());
    for (const auto& j : s.joints) {
        EXPECT_DOUBLE_EQ(j.amplitude, kPi / 2 * 0.5 * (1 + std::tanh(-0.5)));
        EXPECT_DOUBLE_EQ(j.phase, 0.0);
        EXPECT_DOUBLE_EQ(j.offset, kPi / 2 * std::tanh(0.5));
    }
    EXPECT_DOUBLE_EQ(s.frequency, cic::hypergp::evolved_frequency(forest({"x2"}), cfg));
    // Three trees: one per parameter, each asked at the joint.
    const cic::sim::GaitSpec t = cic::hypergp::gait_spec(robot, forest({"0", "x0", "5"}), cfg);
    const auto g = cic::hypergp::substrate_geometry(robot);
    for (std::size_t i = 0; i < t.joints.size(); ++i) {
        EXPECT_DOUBLE_EQ(t.joints[i].amplitude, kPi / 4);
        EXPECT_DOUBLE_EQ(t.joints[i].phase, kPi * std::tanh(g.joints[i].x));
        EXPECT_DOUBLE_EQ(t.joints[i].offset, kPi / 2 * std::tanh(5.0));
    }
}

TEST(EvolvedClock, ThePeriodIsOneOverTheEvolvedFrequency) {
    const auto robot = cic::sim::preset(1, false);
    NeuralConfig cfg;
    cfg.clock_inputs = true;
    cfg.evolve_clock = true;
    const Forest f = forest({"(mul x0 0.5)"});
    const auto c = cic::hypergp::make_neural_controller(robot, f, cfg);
    EXPECT_DOUBLE_EQ(c.clock_period(), 1.0 / cic::hypergp::evolved_frequency(f, cfg));
    cfg.evolve_clock = false;
    EXPECT_EQ(cic::hypergp::make_neural_controller(robot, f, cfg).clock_period(), cfg.clock_period);
}

TEST(MakeController, EverySubstrateDrivesTheRobotAndRecordsItsCommands) {
    const auto robot = cic::sim::preset(1, false);
    const Forest f = forest({"(sin (add (mul x0 x3) (gauss (sub x1 x2))))"});
    for (auto sub : {"network", "cpg", "gait"}) {
        NeuralConfig cfg;
        cfg.substrate = sub;
        auto a = cic::hypergp::make_controller(robot, f, cfg, 0.0125);
        auto b = cic::hypergp::make_controller(robot, f, cfg, 0.0125);
        a->set_recording(true);
        a->reset(12);
        b->reset(12);
        std::vector<double> angles(12), da(12), db(12);
        for (int s = 0; s < 50; ++s) {
            for (int j = 0; j < 12; ++j) angles[j] = 0.5 * std::sin(0.1 * s + j);
            a->step(0.0125 * s, angles, da);
            b->step(0.0125 * s, angles, db);
            ASSERT_EQ(da, db);
            for (double v : da) ASSERT_LE(std::abs(v), kPi);   // a gait's offset + amplitude: clamped by the simulator
        }
        EXPECT_EQ(a->record().steps(), 50u);
        EXPECT_EQ(a->record().commands.size(), 50u * 12u);
        EXPECT_EQ(std::vector<double>(a->record().commands.end() - 12, a->record().commands.end()), da);
        EXPECT_GT(a->connections(), 0u);
    }
}

TEST(GaitCpgEncoding, DecodesTheUnitBoxIntoTheWeightRanges) {
    const auto robot = cic::sim::preset(1, false);
    NeuralConfig cfg;
    cfg.cpg_feedback = 2.0;
    const cic::gait::CpgEncoding e(robot, cfg, 0.0125, cic::gait::Bounds::Reflect);
    const std::size_t n = robot.actuated().size(), edges = cic::sim::cpg_neighbours(robot, 2).size();
    ASSERT_EQ(e.dimension(), 2 * n + edges);
    std::vector<double> x(e.dimension(), 1.0);
    x[0] = 0.0;
    x[1] = 1.25;   // reflected to 0.75
    const cic::sim::CpgSpec s = e.decode(x);
    EXPECT_DOUBLE_EQ(s.self[0], -cfg.cpg_weight_scale);
    EXPECT_DOUBLE_EQ(s.self[1], 0.5 * cfg.cpg_weight_scale);
    EXPECT_DOUBLE_EQ(s.coupling.back(), cfg.cpg_weight_scale);
    EXPECT_DOUBLE_EQ(s.feedback.back(), 2.0);
    EXPECT_THROW(e.decode(std::vector<double>(3, 0.5)), std::invalid_argument);
    x[2] = NAN;
    EXPECT_THROW(e.decode(x), std::invalid_argument);
    cfg.cpg_weight_scale = 0;
    EXPECT_THROW(cic::gait::CpgEncoding(robot, cfg, 0.0125, cic::gait::Bounds::Clamp), std::invalid_argument);
}

} // namespace
