// The recurrent network against hand computation (thesis 6.3.5, eq. 7.2-7.3).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "cic/nn/network.hpp"

using cic::nn::Network;
using cic::nn::NeuronModel;
using cic::nn::SynapseBlocks;
using cic::nn::SynapseType;

namespace {

// A 1x1 block holding w (an empty block when w == 0).
cic::nn::SparseMatrix one(double w) {
    Eigen::MatrixXd m(1, 1);
    m(0, 0) = w;
    return m.sparseView();
}

// One input, one hidden, one output neuron; weights in type order IH HO HH OO OH.
Network tiny(std::array<double, 5> w, NeuronModel model) {
    SynapseBlocks b;
    for (int t = 0; t < 5; ++t) b[t] = one(w[t]);
    return Network(1, 1, 1, std::move(b), model);
}

std::vector<std::array<double, 2>> run(Network& net, const std::vector<double>& inputs) {
    std::vector<std::array<double, 2>> trace;
    for (double x : inputs) {
        double o = 0.0;
        net.step(std::span<const double>(&x, 1), std::span<double>(&o, 1));
        trace.push_back({net.hidden_state()[0], o});
        EXPECT_EQ(o, net.output_state()[0]);
    }
    return trace;
}

} // namespace

// Hand-computed (python, double precision):
//   h_t = tanh(0.5 in_t - 0.7 h_{t-1} + 0.8 o_{t-1}),  o_t = tanh(1.5 h_t + 0.3 o_{t-1})
TEST(Network, TwoNeuronsWithDelayedSynapsesMatchHandComputation) {
    Network net = tiny({0.5, 1.5, -0.7, 0.3, 0.8}, NeuronModel::Tanh);
    const auto got = run(net, {1, 0.5, -1, 0, 0.25});
    const double want[5][2] = {{0.46211715726000974, 0.60001827509812855},
                               {0.38552459837497782, 0.64007003702679499},
                               {-0.25224712709983521, -0.18422215473479925},
                               {0.029186973016316814, -0.011485681788876883},
                               {0.09509238201546516, 0.13830084300522233}};
    for (int t = 0; t < 5; ++t) {
        EXPECT_NEAR(got[t][0], want[t][0], 1e-15) << "hidden, step " << t;
        EXPECT_NEAR(got[t][1], want[t][1], 1e-15) << "output, step " << t;
    }
}

// Without the delayed synapses the output depends on the current input only.
TEST(Network, FeedForwardOnlyHasNoMemory) {
    Network net = tiny({0.5, 1.5, 0, 0, 0}, NeuronModel::Tanh);
    const auto got = run(net, {1, 0.5, -1});
    for (int t = 0; t < 3; ++t) {
        const double in = std::array{1.0, 0.5, -1.0}[t];
        EXPECT_DOUBLE_EQ(got[t][1], std::tanh(1.5 * std::tanh(0.5 * in)));
    }
    EXPECT_EQ(net.synapse_count(), 2u);
    EXPECT_EQ(net.synapse_count(SynapseType::HiddenHidden), 0u);
}

// Integrating neurons: out_t = clamp(out_{t-1} + tanh(sum), -1, 1); clamps at 1 and comes back.
TEST(Network, IntegratingNeuronsMatchHandComputation) {
    Network net = tiny({0.9, 0.8, 0.2, -0.3, 0.1}, NeuronModel::Integrating);
    const auto got = run(net, {1, 1, -1, -1, -1});
    const double want[5][2] = {{0.71629787019902447, 0.51758712208987201},
                               {1, 1},
                               {0.4629504330019647, 1},
                               {-0.14609965495865207, 0.60570148395419454},
                               {-0.8467871252407726, -0.090112904641342362}};
    for (int t = 0; t < 5; ++t) {
        EXPECT_NEAR(got[t][0], want[t][0], 1e-15) << "hidden, step " << t;
        EXPECT_NEAR(got[t][1], want[t][1], 1e-15) << "output, step " << t;
    }
}

TEST(Network, ResetZeroesTheStateSoARunRepeatsExactly) {
    Network net = tiny({0.5, 1.5, -0.7, 0.3, 0.8}, NeuronModel::Tanh);
    const auto first = run(net, {1, 0.5, -1, 0, 0.25});
    net.reset();
    EXPECT_EQ(net.hidden_state()[0], 0.0);
    EXPECT_EQ(net.output_state()[0], 0.0);
    EXPECT_EQ(run(net, {1, 0.5, -1, 0, 0.25}), first);
}

// Two inputs, three hidden, two outputs: rows are targets, columns sources.
TEST(Network, LargerBlocksUseRowsAsTargets) {
    Eigen::MatrixXd ih(3, 2), ho(2, 3);
    ih << 1, 0, 0, 2, -1, 1;
    ho << 1, 1, 0, 0, 0, -1;
    SynapseBlocks b;
    b[0] = ih.sparseView();
    b[1] = ho.sparseView();
    b[2].resize(3, 3);
    b[3].resize(2, 2);
    b[4].resize(3, 2);
    Network net(2, 3, 2, std::move(b));
    const std::array<double, 2> in{0.3, -0.2};
    std::array<double, 2> out{};
    net.step(in, out);
    const double h0 = std::tanh(0.3), h1 = std::tanh(-0.4), h2 = std::tanh(-0.5);
    EXPECT_DOUBLE_EQ(out[0], std::tanh(h0 + h1));
    EXPECT_DOUBLE_EQ(out[1], std::tanh(-h2));
    EXPECT_EQ(net.synapse_count(), 7u);
    EXPECT_EQ(net.dense(SynapseType::InputHidden), ih);
    EXPECT_EQ(net.dense(SynapseType::HiddenOutput), ho);
}

TEST(Network, BadArgumentsThrow) {
    SynapseBlocks b;
    b[0].resize(2, 1);   // IH should be 1x1 for (1, 1, 1)
    for (int t = 1; t < 5; ++t) b[t].resize(1, 1);
    EXPECT_THROW(Network(1, 1, 1, b), std::invalid_argument);

    SynapseBlocks nan_block;
    for (int t = 0; t < 5; ++t) nan_block[t].resize(1, 1);
    nan_block[2].insert(0, 0) = std::nan("");
    EXPECT_THROW(Network(1, 1, 1, nan_block), std::invalid_argument);

    Network net = tiny({1, 1, 0, 0, 0}, NeuronModel::Tanh);
    std::array<double, 2> two{};
    std::array<double, 1> one_value{};
    EXPECT_THROW(net.step(two, one_value), std::invalid_argument);
    EXPECT_THROW(net.step(one_value, two), std::invalid_argument);
}

TEST(Network, ExplicitZerosAreNotSynapses) {
    SynapseBlocks b;
    for (int t = 0; t < 5; ++t) b[t].resize(1, 1);
    b[0].insert(0, 0) = 0.0;
    b[1].insert(0, 0) = 2.0;
    Network net(1, 1, 1, std::move(b));
    EXPECT_EQ(net.synapse_count(SynapseType::InputHidden), 0u);
    EXPECT_EQ(net.synapse_count(), 1u);
}
