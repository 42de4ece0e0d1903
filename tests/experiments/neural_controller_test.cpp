// The neural controller (averaging, recording) and the oscillation penalty.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "cic/core/error.hpp"
#include "cic/nn/substrate.hpp"
#include "cic/experiments/hypergp/neural_controller.hpp"
#include "cic/experiments/hypergp/oscillation.hpp"

using cic::hypergp::NeuralController;
using cic::nn::NeuralConfig;

namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

// One joint, one hidden neuron; IH = HO = 1, nothing delayed, so the output at
// step t is o_t = act(act(angle_t / (pi/2))).
NeuralController one_joint(const NeuralConfig& cfg) {
    cic::nn::Geometry g;
    g.joints = {{0, 0}};
    g.hidden = {{0, 0}};
    auto layout = cic::nn::make_neuron_layout(g, cfg);
    cic::nn::SynapseBlocks b;
    for (auto& m : b) m.resize(1, 1);
    b[0].insert(0, 0) = 1.0;
    b[1].insert(0, 0) = 1.0;
    return NeuralController(cic::nn::Network(1, 1, 1, std::move(b), cfg.neuron), std::move(layout), cfg);
}

const std::vector<double> kAngles{0.3, -0.9, 1.2, 0.1, 0.5, -0.4, 0.8};

std::vector<double> drive(NeuralController& c) {
    c.reset(1);
    std::vector<double> desired;
    for (std::size_t s = 0; s < kAngles.size(); ++s) {
        double d = -99.0;
        c.step(0.0125 * static_cast<double>(s), std::span<const double>(&kAngles[s], 1), std::span<double>(&d, 1));
        desired.push_back(d);
    }
    return desired;
}

double o(double angle) { return std::tanh(std::tanh(angle / kHalfPi)); }

} // namespace

TEST(NeuralController, WithoutAveragingTheCommandIsTheOutputTimesHalfPi) {
    NeuralConfig cfg;
    auto c = one_joint(cfg);
    const auto d = drive(c);
    for (std::size_t s = 0; s < kAngles.size(); ++s) EXPECT_DOUBLE_EQ(d[s], o(kAngles[s]) * kHalfPi) << s;
}

// n = 3: command 0 for steps 0, 1; at step 2 the mean of outputs 0..2, held on
// steps 3, 4; at step 5 the mean of outputs 3..5, held on step 6.
TEST(NeuralController, AveragingUpdatesEveryNStepsWithTheMeanOfTheLastN) {
    NeuralConfig cfg;
    cfg.sample_average_count = 3;
    auto c = one_joint(cfg);
    c.set_recording(true);
    const auto d = drive(c);
    const double first = (o(0.3) + o(-0.9) + o(1.2)) / 3 * kHalfPi;
    const double second = (o(0.1) + o(0.5) + o(-0.4)) / 3 * kHalfPi;
    const std::vector<double> want{0, 0, first, first, first, second, second};
    ASSERT_EQ(d.size(), want.size());
    for (std::size_t s = 0; s < want.size(); ++s) EXPECT_NEAR(d[s], want[s], 1e-15) << s;

    const auto& rec = c.record();
    EXPECT_EQ(rec.joints, 1u);
    EXPECT_EQ(rec.steps(), kAngles.size());
    EXPECT_EQ(rec.commands, d);
    EXPECT_DOUBLE_EQ(rec.outputs[4], o(0.5));
    EXPECT_DOUBLE_EQ(rec.times[2], 0.025);

    // reset() starts a fresh window and clears the record.
    EXPECT_EQ(drive(c), d);
    EXPECT_EQ(c.record().steps(), kAngles.size());
}

// Integrating neurons with n = 2: h_t = clamp(h_{t-1} + tanh(in_t)), o_t = clamp(o_{t-1} + tanh(h_t)).
TEST(NeuralController, IntegratingNeuronsWithAveraging) {
    NeuralConfig cfg;
    cfg.neuron = cic::nn::NeuronModel::Integrating;
    cfg.sample_average_count = 2;
    auto c = one_joint(cfg);
    c.set_recording(true);
    const auto d = drive(c);
    double h = 0, out = 0;
    std::vector<double> outs;
    for (double a : kAngles) {
        h = std::clamp(h + std::tanh(a / kHalfPi), -1.0, 1.0);
        out = std::clamp(out + std::tanh(h), -1.0, 1.0);
        outs.push_back(out);
    }
    EXPECT_EQ(c.record().outputs, outs);
    EXPECT_EQ(d[0], 0.0);
    EXPECT_DOUBLE_EQ(d[1], (outs[0] + outs[1]) / 2 * kHalfPi);
    EXPECT_DOUBLE_EQ(d[2], d[1]);
    EXPECT_DOUBLE_EQ(d[5], (outs[4] + outs[5]) / 2 * kHalfPi);
    EXPECT_DOUBLE_EQ(d[6], d[5]);
}

TEST(NeuralController, BadArgumentsThrow) {
    NeuralConfig cfg;
    auto c = one_joint(cfg);
    EXPECT_THROW(c.reset(2), std::invalid_argument);
    c.reset(1);
    std::vector<double> two(2), one(1);
    EXPECT_THROW(c.step(0, one, two), std::invalid_argument);
    EXPECT_THROW(c.step(0, two, one), std::invalid_argument);
    cfg.sample_average_count = 0;
    EXPECT_THROW(one_joint(cfg), cic::InputError);
}

TEST(NeuralController, SameGenotypeOnR1GivesIdenticalCommands) {
    NeuralConfig cfg;
    const cic::tree::Forest g{cic::tree::Tree::parse("(sin (add (mul x0 x3) (gauss (sub x1 x2))))")};
    const auto robot = cic::sim::preset(1, false);
    auto a = cic::hypergp::make_neural_controller(robot, g, cfg);
    auto b = cic::hypergp::make_neural_controller(robot, g, cfg);
    EXPECT_EQ(a.network().output_count(), 12u);
    EXPECT_EQ(a.network().hidden_count(), 19u);
    EXPECT_GT(a.network().synapse_count(), 0u);
    a.reset(12);
    b.reset(12);
    std::vector<double> angles(12), da(12), db(12);
    for (int s = 0; s < 50; ++s) {
        for (int j = 0; j < 12; ++j) angles[j] = 0.5 * std::sin(0.1 * s + j);
        a.step(0.0125 * s, angles, da);
        b.step(0.0125 * s, angles, db);
        ASSERT_EQ(da, db);
        for (double v : da) ASSERT_LE(std::abs(v), kHalfPi);
    }
}

// ---- oscillation penalty ----------------------------------------------------

TEST(Oscillation, DominantFrequencyOfKnownSignals) {
    const double dt = 0.0125;
    std::vector<double> c;   // joint 0: +-0.5 every step (40 Hz); joint 1: constant
    for (int s = 0; s < 81; ++s) {
        c.push_back(s % 2 ? -0.5 : 0.5);
        c.push_back(0.3);
    }
    EXPECT_DOUBLE_EQ(cic::hypergp::dominant_frequency(c, 2, dt), 40.0);

    std::vector<double> sine;   // 1 Hz over 10 s
    for (int s = 0; s <= 800; ++s) sine.push_back(0.8 * std::sin(2 * std::numbers::pi * s * dt + 0.3));
    EXPECT_NEAR(cic::hypergp::dominant_frequency(sine, 1, dt), 1.0, 0.05);

    std::vector<double> noise;  // below the hysteresis band: no crossing
    for (int s = 0; s < 100; ++s) noise.push_back(s % 2 ? 0.004 : -0.004);
    EXPECT_EQ(cic::hypergp::dominant_frequency(noise, 1, dt), 0.0);
}

TEST(Oscillation, PenaltiesMatchHandComputation) {
    NeuralConfig cfg;
    // 3 steps, 2 joints: changes |1-0| + |0-0| + |1-1| + |0.5-0| = 1.5 over 4 -> 0.375.
    const std::vector<double> c{0, 0, 1, 0, 1, 0.5};
    EXPECT_DOUBLE_EQ(cic::hypergp::mean_command_change(c, 2), 0.375);
    EXPECT_EQ(cic::hypergp::penalised_fitness(1.5, cfg, c, 2, 0.0125), 1.5);   // None
    cfg.penalty = cic::nn::OscillationPenalty::CommandChange;
    cfg.penalty_weight = 2.0;
    EXPECT_DOUBLE_EQ(cic::hypergp::penalised_fitness(1.5, cfg, c, 2, 0.0125), 0.75);

    cfg.penalty = cic::nn::OscillationPenalty::Frequency;
    cfg.penalty_max_frequency = 2.0;
    std::vector<double> shake;   // 40 Hz
    for (int s = 0; s < 81; ++s) shake.push_back(s % 2 ? -0.5 : 0.5);
    const double k = std::exp(2.0 - 40.0);
    EXPECT_DOUBLE_EQ(cic::hypergp::frequency_factor(40.0, 2.0), k);
    EXPECT_EQ(cic::hypergp::frequency_factor(1.5, 2.0), 1.0);
    EXPECT_DOUBLE_EQ(cic::hypergp::penalised_fitness(3.0, cfg, shake, 1, 0.0125), 3.0 * k);
    EXPECT_DOUBLE_EQ(cic::hypergp::penalised_fitness(-3.0, cfg, shake, 1, 0.0125), -3.0 / k);
    // A slow gait is not touched.
    std::vector<double> slow;
    for (int s = 0; s <= 800; ++s) slow.push_back(0.8 * std::sin(2 * std::numbers::pi * 0.5 * s * 0.0125));
    EXPECT_EQ(cic::hypergp::penalised_fitness(3.0, cfg, slow, 1, 0.0125), 3.0);
}

TEST(Oscillation, BadArgumentsThrow) {
    const std::vector<double> c{0, 1, 2};
    EXPECT_THROW(cic::hypergp::dominant_frequency(c, 2, 0.1), std::invalid_argument);
    EXPECT_THROW(cic::hypergp::dominant_frequency(c, 0, 0.1), std::invalid_argument);
    EXPECT_THROW(cic::hypergp::dominant_frequency(c, 1, 0.0), std::invalid_argument);
    EXPECT_THROW(cic::hypergp::dominant_frequency(c, 1, 0.1, -1.0), std::invalid_argument);
    EXPECT_THROW(cic::hypergp::mean_command_change(c, 2), std::invalid_argument);
    EXPECT_THROW(cic::hypergp::frequency_factor(3.0, 0.0), std::invalid_argument);
    EXPECT_EQ(cic::hypergp::dominant_frequency(std::vector<double>{0.5}, 1, 0.1), 0.0);
}
