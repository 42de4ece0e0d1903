// Hypercube encoding: a hand-written CPPF gives exactly the expected weights.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "cic/core/error.hpp"
#include "cic/nn/substrate.hpp"
#include "cic/tree/tree.hpp"

using cic::nn::Geometry;
using cic::nn::NeuralConfig;
using cic::nn::SynapseType;
using cic::tree::Tree;

namespace {

// Joints at x = -1, 0.5; hidden at x = -1, -0.5, 0.25, 1 (y = 0 everywhere).
Geometry small_geometry() {
    Geometry g;
    g.joints = {{-1, 0}, {0.5, 0}};
    g.hidden = {{-1, 0}, {-0.5, 0}, {0.25, 0}, {1, 0}};
    return g;
}

Eigen::MatrixXd mat(int rows, int cols, std::initializer_list<double> v) {
    Eigen::MatrixXd m(rows, cols);
    auto it = v.begin();
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) m(r, c) = *it++;
    return m;
}

// w = x1 - x2 (thesis names) = source x - target x = "(sub x0 x2)".
cic::tree::Forest source_minus_target() { return {Tree::parse("(sub x0 x2)")}; }

} // namespace

// Threshold 0.75: |w| >= 0.75 survives (0.75 itself too), 0.5 and 0.25 do not.
TEST(Substrate, HandWrittenCppfGivesExactWeightMatrices) {
    NeuralConfig cfg;
    cfg.threshold = 0.75;
    const auto net = cic::nn::build_network(small_geometry(), source_minus_target(), cfg);
    ASSERT_EQ(net.input_count(), 2u);
    ASSERT_EQ(net.hidden_count(), 4u);
    ASSERT_EQ(net.output_count(), 2u);
    const auto ih = mat(4, 2, {0, 1.5, 0, 1.0, -1.25, 0, -2, 0});
    EXPECT_EQ(net.dense(SynapseType::InputHidden), ih);
    EXPECT_EQ(net.dense(SynapseType::HiddenOutput), mat(2, 4, {0, 0, 1.25, 2, -1.5, -1.0, 0, 0}));
    EXPECT_EQ(net.dense(SynapseType::HiddenHidden),
              mat(4, 4, {0, 0, 1.25, 2, 0, 0, 0.75, 1.5, -1.25, -0.75, 0, 0.75, -2, -1.5, -0.75, 0}));
    EXPECT_EQ(net.dense(SynapseType::OutputOutput), mat(2, 2, {0, 1.5, -1.5, 0}));
    EXPECT_EQ(net.dense(SynapseType::OutputHidden), ih);
    EXPECT_EQ(net.synapse_count(), 4u + 4u + 10u + 2u + 4u);
}

TEST(Substrate, DisabledTypesHaveNoSynapses) {
    NeuralConfig cfg;
    cfg.threshold = 0.75;
    cfg.synapse_enabled = {true, true, false, true, false};
    const auto net = cic::nn::build_network(small_geometry(), source_minus_target(), cfg);
    EXPECT_EQ(net.synapse_count(SynapseType::HiddenHidden), 0u);
    EXPECT_EQ(net.synapse_count(SynapseType::OutputHidden), 0u);
    EXPECT_EQ(net.dense(SynapseType::HiddenHidden), Eigen::MatrixXd::Zero(4, 4));
    EXPECT_EQ(net.dense(SynapseType::OutputOutput), mat(2, 2, {0, 1.5, -1.5, 0}));
    EXPECT_EQ(net.synapse_count(SynapseType::InputHidden), 4u);
}

TEST(Substrate, DefaultForestMapIsTypeModuloTrees) {
    NeuralConfig cfg;
    EXPECT_EQ(cic::nn::resolve_forest_map(cfg, 1), (std::array<int, 5>{0, 0, 0, 0, 0}));
    EXPECT_EQ(cic::nn::resolve_forest_map(cfg, 2), (std::array<int, 5>{0, 1, 0, 1, 0}));
    EXPECT_EQ(cic::nn::resolve_forest_map(cfg, 4), (std::array<int, 5>{0, 1, 2, 3, 0}));
    cfg.forest_map = {1, 1, 0, 0, 1};
    EXPECT_EQ(cic::nn::resolve_forest_map(cfg, 2), (std::array<int, 5>{1, 1, 0, 0, 1}));
}

// Tree 0 answers x_src - x_dst, tree 1 the constant 0.5 (threshold 0.5): each type reads its own tree.
TEST(Substrate, ForestMapPicksTheTreePerType) {
    NeuralConfig cfg;
    const cic::tree::Forest forest{Tree::parse("(sub x0 x2)"), Tree::parse("(mul 0.5 1)")};
    cfg.forest_map = {1, 0, 1, 0, 1};  // IH, HH, OH from the constant tree
    cfg.threshold = 0.5;
    const auto net = cic::nn::build_network(small_geometry(), forest, cfg);
    EXPECT_EQ(net.dense(SynapseType::InputHidden), Eigen::MatrixXd::Constant(4, 2, 0.5));
    EXPECT_EQ(net.dense(SynapseType::HiddenHidden), Eigen::MatrixXd::Constant(4, 4, 0.5));
    EXPECT_EQ(net.dense(SynapseType::OutputHidden), Eigen::MatrixXd::Constant(4, 2, 0.5));
    EXPECT_EQ(net.dense(SynapseType::OutputOutput), mat(2, 2, {0, 1.5, -1.5, 0}));
    EXPECT_EQ(net.dense(SynapseType::HiddenOutput), mat(2, 4, {0, 0.5, 1.25, 2, -1.5, -1.0, 0, 0.5}));
}

TEST(Substrate, WeightRules) {
    NeuralConfig cfg;   // threshold 0.2, Raw
    EXPECT_EQ(cic::nn::apply_weight_rule(0.2, cfg), 0.2);
    EXPECT_EQ(cic::nn::apply_weight_rule(-7.0, cfg), -7.0);
    EXPECT_EQ(cic::nn::apply_weight_rule(0.1999, cfg), 0.0);
    EXPECT_EQ(cic::nn::apply_weight_rule(std::nan(""), cfg), 0.0);
    EXPECT_EQ(cic::nn::apply_weight_rule(INFINITY, cfg), 0.0);
    cfg.weight_rule = cic::nn::WeightRule::Scaled;
    cfg.max_weight = 3.0;
    EXPECT_DOUBLE_EQ(cic::nn::apply_weight_rule(0.6, cfg), 1.5);     // (0.6-0.2)/0.8*3
    EXPECT_DOUBLE_EQ(cic::nn::apply_weight_rule(-0.6, cfg), -1.5);
    EXPECT_EQ(cic::nn::apply_weight_rule(-2.0, cfg), -3.0);          // |w| clamped to 1
    EXPECT_EQ(cic::nn::apply_weight_rule(0.2, cfg), 0.0);            // at the threshold: weight 0, dropped
    EXPECT_EQ(cic::nn::apply_weight_rule(0.1, cfg), 0.0);
}

// Extra CPPF inputs: x4 = source layer, x5 = target layer (-1 input, 0 hidden, 1 output), x6 = distance.
TEST(Substrate, ExtraCppfInputsCarryLayersAndDistance) {
    NeuralConfig cfg;
    cfg.threshold = 0.0;
    cfg.extra_cppf_inputs = true;
    EXPECT_EQ(cic::nn::cppf_variable_count(cfg), 7);
    auto net = cic::nn::build_network(small_geometry(), {Tree::parse("(add x4 x5)")}, cfg);
    EXPECT_EQ(net.dense(SynapseType::InputHidden), Eigen::MatrixXd::Constant(4, 2, -1.0));
    EXPECT_EQ(net.dense(SynapseType::HiddenOutput), Eigen::MatrixXd::Constant(2, 4, 1.0));
    EXPECT_EQ(net.synapse_count(SynapseType::HiddenHidden), 0u);    // weight 0 is no synapse
    EXPECT_EQ(net.dense(SynapseType::OutputOutput), Eigen::MatrixXd::Constant(2, 2, 2.0));
    EXPECT_EQ(net.dense(SynapseType::OutputHidden), Eigen::MatrixXd::Constant(4, 2, 1.0));

    Geometry g;
    g.joints = {{0, 0}};
    g.hidden = {{0.6, 0.8}};
    net = cic::nn::build_network(g, {Tree::parse("x6")}, cfg);
    EXPECT_DOUBLE_EQ(net.dense(SynapseType::InputHidden)(0, 0), 1.0);
    EXPECT_EQ(net.synapse_count(SynapseType::OutputOutput), 0u);

    cfg.extra_cppf_inputs = false;   // then only x0..x3 exist
    EXPECT_EQ(cic::nn::cppf_variable_count(cfg), 4);
    EXPECT_THROW(cic::nn::build_network(g, {Tree::parse("x4")}, cfg), std::invalid_argument);
}

TEST(Substrate, BiasAndClockInputs) {
    NeuralConfig cfg;
    cfg.threshold = 0.75;
    cfg.bias_input = true;
    cfg.clock_inputs = true;
    cfg.clock_period = 2.0;
    const auto layout = cic::nn::make_neuron_layout(small_geometry(), cfg);
    ASSERT_EQ(layout.input.size(), 5u);
    EXPECT_EQ(layout.input[2], cic::nn::kBiasPoint);
    EXPECT_EQ(layout.input[3], cic::nn::kClockSinPoint);
    EXPECT_EQ(layout.input[4], cic::nn::kClockCosPoint);
    EXPECT_EQ(layout.output.size(), 2u);

    const auto net = cic::nn::build_network(layout, source_minus_target(), cfg);
    ASSERT_EQ(net.input_count(), 5u);
    // bias at x = 0 into hidden x = 1: w = -1; into hidden x = -0.5: 0.5 < 0.75, dropped.
    EXPECT_EQ(net.dense(SynapseType::InputHidden)(3, 2), -1.0);
    EXPECT_EQ(net.dense(SynapseType::InputHidden)(1, 2), 0.0);

    const std::vector<double> angles{std::numbers::pi / 2, -std::numbers::pi / 4};
    std::vector<double> in(5);
    cic::nn::encode_inputs(layout, cfg, 0.25, angles, in);
    EXPECT_DOUBLE_EQ(in[0], 1.0);
    EXPECT_DOUBLE_EQ(in[1], -0.5);
    EXPECT_EQ(in[2], 1.0);
    EXPECT_DOUBLE_EQ(in[3], std::sin(std::numbers::pi / 4));   // 2 pi 0.25 / 2
    EXPECT_DOUBLE_EQ(in[4], std::cos(std::numbers::pi / 4));
    EXPECT_THROW(cic::nn::encode_inputs(layout, cfg, 0.0, angles, std::span<double>(in).first(4)),
                 std::invalid_argument);
}

TEST(Substrate, SameGenotypeGivesAnIdenticalNetwork) {
    NeuralConfig cfg;
    const cic::tree::Forest g{Tree::parse("(sin (add (mul x0 x3) (gauss (sub x1 x2))))")};
    Geometry geo = small_geometry();
    geo.joints[1].y = 0.3;
    geo.hidden[2].y = -0.7;
    auto a = cic::nn::build_network(geo, g, cfg);
    auto b = cic::nn::build_network(geo, g, cfg);
    for (int t = 0; t < 5; ++t)
        EXPECT_EQ(a.dense(static_cast<SynapseType>(t)), b.dense(static_cast<SynapseType>(t)));
    EXPECT_GT(a.synapse_count(), 0u);
    const std::vector<double> in{0.3, -0.9};
    std::vector<double> oa(2), ob(2);
    for (int s = 0; s < 20; ++s) {
        a.step(in, oa);
        b.step(in, ob);
        ASSERT_EQ(oa, ob);
    }
}

TEST(Substrate, BadArgumentsThrow) {
    const auto geo = small_geometry();
    NeuralConfig cfg;
    cfg.threshold = -0.1;
    EXPECT_THROW(cic::nn::build_network(geo, source_minus_target(), cfg), cic::InputError);
    cfg = {};
    cfg.forest_map = {0, 0, 1, 0, 0};   // tree 1 of a 1-tree genotype
    EXPECT_THROW(cic::nn::build_network(geo, source_minus_target(), cfg), cic::InputError);
    cfg.forest_map = {0, 0, 0};
    EXPECT_THROW(cic::nn::validate(cfg, 1), cic::InputError);
    cfg = {};
    cfg.synapse_enabled = {true, true};
    EXPECT_THROW(cic::nn::validate(cfg, 1), cic::InputError);
    cfg = {};
    cfg.sample_average_count = 0;
    EXPECT_THROW(cic::nn::validate(cfg, 1), cic::InputError);
    cfg = {};
    cfg.weight_rule = cic::nn::WeightRule::Scaled;
    cfg.threshold = 1.0;
    EXPECT_THROW(cic::nn::validate(cfg, 1), cic::InputError);
    cfg = {};
    cfg.clock_period = 0.0;
    EXPECT_THROW(cic::nn::validate(cfg, 1), cic::InputError);
    cfg = {};
    EXPECT_THROW(cic::nn::validate(cfg, 0), cic::InputError);
    EXPECT_NO_THROW(cic::nn::validate(cfg, 1));

    EXPECT_THROW(cic::nn::build_network(geo, {}, cfg), std::invalid_argument);
    EXPECT_THROW(cic::nn::build_network(geo, {Tree()}, cfg), std::invalid_argument);
    Geometry no_joints;
    no_joints.hidden = {{0, 0}};
    EXPECT_THROW(cic::nn::build_network(no_joints, source_minus_target(), cfg), std::invalid_argument);
    Geometry nan_point = geo;
    nan_point.hidden[0].x = std::nan("");
    EXPECT_THROW(cic::nn::build_network(nan_point, source_minus_target(), cfg), std::invalid_argument);
}
