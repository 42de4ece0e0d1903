#pragma once
// Hypercube encoding (thesis 3.4): the genotype (a forest of CPPF trees) is
// queried for the weight of every source/target pair of every enabled synapse
// type, one batch evaluation per tree, and the answers become a Network.
#include <array>
#include <cstddef>
#include <span>

#include "cic/nn/config.hpp"
#include "cic/nn/geometry.hpp"
#include "cic/nn/network.hpp"
#include "cic/tree/tree.hpp"

namespace cic::nn {

// Checks the config for a genotype of `trees` trees. Throws cic::InputError
// naming the field: threshold < 0 or not finite; Scaled with threshold >= 1 or
// max_weight <= 0; sample_average_count < 1; synapse_enabled not of size 5;
// forest_map not empty and not of size 5, or an index outside [0, trees);
// clock_period <= 0; penalty_max_frequency <= 0; penalty_weight < 0; trees == 0.
void validate(const NeuralConfig& cfg, std::size_t trees);

// The tree index used for each synapse type: cfg.forest_map if given, else
// type i -> tree (i mod trees). Validates like validate().
std::array<int, kSynapseTypes> resolve_forest_map(const NeuralConfig& cfg, std::size_t trees);

// The weight rule. Returns 0 for "no synapse": |w| < threshold, or w not finite.
//   Raw:    w
//   Scaled: sign(w) * (min(|w|, 1) - threshold) / (1 - threshold) * max_weight
//           (SharpNEAT; a value at the threshold maps to 0 and is dropped too)
double apply_weight_rule(double w, const NeuralConfig& cfg);

// Builds the network. Throws std::invalid_argument for an empty forest or tree,
// a tree using a variable >= cppf_variable_count(cfg), or a bad geometry;
// cic::InputError for a bad config (see validate).
Network build_network(const Geometry& g, const tree::Forest& genotype, const NeuralConfig& cfg);
Network build_network(const NeuronLayout& layout, const tree::Forest& genotype, const NeuralConfig& cfg);

// Fills the input vector: angle_j / (pi/2) for each joint, then 1 (bias),
// then sin(2 pi t / clock_period), cos(2 pi t / clock_period) as the layout says.
// in.size() must be layout.input.size(), angles.size() layout.joint_count.
void encode_inputs(const NeuronLayout& layout, const NeuralConfig& cfg, double t,
                   std::span<const double> angles, std::span<double> in);

} // namespace cic::nn
