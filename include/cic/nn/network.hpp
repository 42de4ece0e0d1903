#pragma once
// The phenotype: a three-layer recurrent network (thesis 6.3.5, fig. 6.8).
// One step:
//   h_t = act(W_ih in_t + W_hh h_{t-1} + W_oh o_{t-1})
//   o_t = act(W_ho h_t  + W_oo o_{t-1})
// act = tanh, or the integrating neuron of thesis eq. 7.2-7.3:
//   rel = tanh(sum), out_t = clamp(out_{t-1} + rel, -1, 1).
// Blocks are row-major sparse matrices (row = target neuron, column = source),
// so the cost of a step is proportional to the number of synapses.
#include <array>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "cic/nn/config.hpp"

namespace cic::nn {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// Indexed by SynapseType. Shapes (rows x cols): IH H x I, HO O x H, HH H x H,
// OO O x O, OH H x O.
using SynapseBlocks = std::array<SparseMatrix, kSynapseTypes>;

class Network {
public:
    // Throws std::invalid_argument if a block has the wrong shape or a non-finite weight.
    Network(std::size_t inputs, std::size_t hidden, std::size_t outputs, SynapseBlocks blocks,
            NeuronModel model = NeuronModel::Tanh);

    std::size_t input_count() const { return inputs_; }
    std::size_t hidden_count() const { return h_.size(); }
    std::size_t output_count() const { return o_.size(); }
    NeuronModel model() const { return model_; }

    // Zeroes hidden and output state (the delayed synapses then read 0).
    void reset();
    // One network step. inputs.size() == input_count(), outputs.size() == output_count()
    // (throws std::invalid_argument otherwise). Writes o_t to outputs. No allocation.
    void step(std::span<const double> inputs, std::span<double> outputs);

    std::span<const double> hidden_state() const { return h_; }
    std::span<const double> output_state() const { return o_; }

    std::size_t synapse_count() const;
    std::size_t synapse_count(SynapseType t) const;
    const SparseMatrix& matrix(SynapseType t) const { return blocks_[static_cast<int>(t)]; }
    Eigen::MatrixXd dense(SynapseType t) const;   // a copy, for tests and traces

private:
    std::size_t inputs_;
    SynapseBlocks blocks_;
    NeuronModel model_;
    std::vector<double> h_, o_;          // state at t-1 (after step: at t)
    std::vector<double> h_next_, o_next_;
};

std::string_view name(SynapseType t);    // "IH", "HO", "HH", "OO", "OH"

} // namespace cic::nn
