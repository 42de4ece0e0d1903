#pragma once
// Asking the genotype for single numbers: the CPG's weights, a gait's
// parameters, an evolved frequency (docs/hypergp.md). Each number is one query
// (x1, y1, x2, y2) of one tree of the forest, as the network's synapses are.
// A joint's own parameters are asked at (joint, parameter point): the second
// point names the parameter. The parameter points sit on a row below the
// robot's [-1, 1] box, apart from the network's bias and clock row above it,
// so no query coincides with one between real neurons.
#include <cstddef>
#include <span>
#include <vector>

#include "cic/nn/config.hpp"
#include "cic/nn/geometry.hpp"
#include "cic/tree/tree.hpp"

namespace cic::hypergp {

inline constexpr nn::Point kFrequencyPoint{-1.5, -1.5};   // asked as (F, F)
inline constexpr nn::Point kAmplitudePoint{-0.5, -1.5};
inline constexpr nn::Point kPhasePoint{0.0, -1.5};
inline constexpr nn::Point kOffsetPoint{0.5, -1.5};
inline constexpr nn::Point kFeedbackPoint{1.0, -1.5};

struct Query {
    std::size_t tree = 0;          // index into the forest
    nn::Point src, dst;
    // With extraCppfInputs the tree also sees these layer indices and the
    // distance between the points. Joints are output neurons.
    double src_layer = nn::kOutputLayer;
    double dst_layer = nn::kOutputLayer;
};

// The answers, in query order: one batch evaluation per tree. Throws
// std::invalid_argument for a query of a tree the forest lacks, an empty tree
// or a tree using more variables than nn::cppf_variable_count(cfg).
std::vector<double> ask(const tree::Forest& genotype, const nn::NeuralConfig& cfg, std::span<const Query> queries);

// tanh(v), with NaN read as 0 (a tree may divide 0 by 0's protected twin and
// still give NaN through inf - inf): every parameter is a smooth, bounded
// function of the tree's answer.
double squash(double v);
// (1 + squash(v)) / 2, in (0, 1).
double unit(double v);

// f_min + (f_max - f_min) unit(tree 0 at (F, F)), Hz: the evolved frequency.
double evolved_frequency(const tree::Forest& genotype, const nn::NeuralConfig& cfg);
// Its position in the range, in [0, 1]: unit(T_0(F, F)).
double evolved_frequency_unit(const tree::Forest& genotype, const nn::NeuralConfig& cfg);

} // namespace cic::hypergp
