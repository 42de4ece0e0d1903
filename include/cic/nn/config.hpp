#pragma once
// Plain settings of the substrate, network and neural controller.
#include <string>
#include <vector>

namespace cic::nn {

// Synapse types of thesis fig. 6.8. IH and HO act at once; HH, OO and OH one step later.
enum class SynapseType { InputHidden = 0, HiddenOutput = 1, HiddenHidden = 2, OutputOutput = 3, OutputHidden = 4 };
inline constexpr int kSynapseTypes = 5;

enum class WeightRule { Raw, Scaled };          // raw CPPF value, or SharpNEAT-style rescale to +-max_weight
enum class NeuronModel { Tanh, Integrating };   // thesis eq. 7.2-7.3
enum class OscillationPenalty { None, Frequency, CommandChange };
// Where the substrate's neurons sit (Neural.substrateLayout; the HyperGP
// experiments compute the geometry, experiments/hypergp/substrate_geometry.hpp).
enum class SubstrateLayout { Normalised, Absolute };

struct NeuralConfig {
    double threshold = 0.2;                 // synopsisThreshold: |w| < threshold -> no synapse
    bool middle_legs = false;               // useMiddleLegs (robot choice; kept here as in the thesis)
    int sample_average_count = 1;           // sampleAverageCount
    std::vector<bool> synapse_enabled = {true, true, true, true, true};   // by SynapseType
    // Forest map: tree index per synapse type (used when the genotype has > 1 tree).
    // Default for 1 tree: all 0. Default for n trees: type i -> tree (i mod n).
    std::vector<int> forest_map;            // empty = default
    WeightRule weight_rule = WeightRule::Raw;
    double max_weight = 3.0;                // for Scaled
    NeuronModel neuron = NeuronModel::Tanh;
    bool bias_input = false;
    bool clock_inputs = false;              // sin/cos clock inputs
    double clock_period = 1.0;              // s
    bool extra_cppf_inputs = false;         // layer index and distance as extra CPPF variables
    OscillationPenalty penalty = OscillationPenalty::None;
    double penalty_max_frequency = 2.0;     // Hz, for Frequency
    double penalty_weight = 1.0;            // for CommandChange
    // Beyond the thesis (docs/hypergp.md); the defaults are the thesis's network.
    // What the HyperGP genotype is queried to build (docs/hypergp.md): "network"
    // (the thesis's recurrent network), "cpg" (coupled oscillators), "gait" (an
    // open-loop gait), or a controller registered by name
    // (experiments/hypergp/controller.hpp, io/substrate_names.hpp).
    std::string substrate = "network";
    bool evolve_clock = false;              // network: the clock's frequency comes from the genotype
    double frequency_min = 0.1;             // Hz: range of an evolved frequency (evolved clock, gait)
    double frequency_max = 3.0;
    double cpg_weight_scale = 6.283185307179586;   // rad/s: w = scale * tanh(tree)
    int cpg_hops = 2;                       // joints at most this many links apart are coupled
    double cpg_feedback = 0.0;              // 1/s: largest feedback gain; 0 = open loop
    // Offset-HybrID (substrate gait; docs/hypergp.md): one directly encoded
    // offset per joint beside the trees, moved by N(0, offset_sigma) steps (in
    // units of pi/2) with probability offset_rate in each bred child.
    bool direct_offsets = false;
    double offset_sigma = 0.2;
    double offset_rate = 0.25;
    // Switch-HybrID (substrate gait; docs/hypergp.md): the run hands over to
    // CMA-ES on the direct gait (the Gait.* keys) after switch_patience
    // generations without improvement of the best, or once HyperGP has spent
    // switch_share of the budget Gait.evaluations; 0 = that rule is off.
    int switch_patience = 0;
    double switch_share = 0.0;
    bool switches() const { return switch_patience > 0 || switch_share > 0; }
    // Normalised: the robot's bounding box onto [-1, 1] per axis (the
    // thesis's); Absolute: cells from the robot's centre module divided by
    // substrate_unit, so the coordinates do not depend on the body's size.
    SubstrateLayout substrate_layout = SubstrateLayout::Normalised;
    double substrate_unit = 3.0;   // cells per unit, for Absolute
};

} // namespace cic::nn
