#include "cic/nn/network.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cic::nn {

namespace {

struct Shape {
    std::size_t rows, cols;
};

// Adds row r of a compressed row-major block times x to sum.
inline double row_dot(const SparseMatrix& m, Eigen::Index r, const double* x) {
    const auto* outer = m.outerIndexPtr();
    const auto* inner = m.innerIndexPtr();
    const double* val = m.valuePtr();
    double s = 0.0;
    for (auto k = outer[r]; k < outer[r + 1]; ++k) s += val[k] * x[inner[k]];
    return s;
}

inline double activate(NeuronModel model, double sum, double previous) {
    const double rel = std::tanh(sum);
    if (model == NeuronModel::Tanh) return rel;
    return std::clamp(previous + rel, -1.0, 1.0);   // integrating neuron, eq. 7.2-7.3
}

} // namespace

std::string_view name(SynapseType t) {
    switch (t) {
    case SynapseType::InputHidden: return "IH";
    case SynapseType::HiddenOutput: return "HO";
    case SynapseType::HiddenHidden: return "HH";
    case SynapseType::OutputOutput: return "OO";
    case SynapseType::OutputHidden: return "OH";
    }
    throw std::invalid_argument("nn::name: unknown synapse type");
}

Network::Network(std::size_t inputs, std::size_t hidden, std::size_t outputs, SynapseBlocks blocks,
                 NeuronModel model)
    : inputs_(inputs), blocks_(std::move(blocks)), model_(model), h_(hidden, 0.0), o_(outputs, 0.0),
      h_next_(hidden, 0.0), o_next_(outputs, 0.0) {
    const std::array<Shape, kSynapseTypes> shapes{{
        {hidden, inputs}, {outputs, hidden}, {hidden, hidden}, {outputs, outputs}, {hidden, outputs}}};
    for (int t = 0; t < kSynapseTypes; ++t) {
        auto& m = blocks_[t];
        const auto want = shapes[t];
        if (static_cast<std::size_t>(m.rows()) != want.rows || static_cast<std::size_t>(m.cols()) != want.cols)
            throw std::invalid_argument(
                "nn::Network: block " + std::string(name(static_cast<SynapseType>(t))) + " is " +
                std::to_string(m.rows()) + "x" + std::to_string(m.cols()) + ", expected " +
                std::to_string(want.rows) + "x" + std::to_string(want.cols));
        m.prune([](Eigen::Index, Eigen::Index, double v) { return v != 0.0; });
        m.makeCompressed();
        for (Eigen::Index k = 0; k < m.nonZeros(); ++k)
            if (!std::isfinite(m.valuePtr()[k]))
                throw std::invalid_argument("nn::Network: block " +
                                            std::string(name(static_cast<SynapseType>(t))) +
                                            " has a non-finite weight");
    }
}

void Network::reset() {
    std::fill(h_.begin(), h_.end(), 0.0);
    std::fill(o_.begin(), o_.end(), 0.0);
}

void Network::step(std::span<const double> inputs, std::span<double> outputs) {
    if (inputs.size() != inputs_ || outputs.size() != o_.size())
        throw std::invalid_argument("nn::Network::step: got " + std::to_string(inputs.size()) + " inputs and " +
                                    std::to_string(outputs.size()) + " outputs, expected " +
                                    std::to_string(inputs_) + " and " + std::to_string(o_.size()));
    const auto& ih = blocks_[static_cast<int>(SynapseType::InputHidden)];
    const auto& ho = blocks_[static_cast<int>(SynapseType::HiddenOutput)];
    const auto& hh = blocks_[static_cast<int>(SynapseType::HiddenHidden)];
    const auto& oo = blocks_[static_cast<int>(SynapseType::OutputOutput)];
    const auto& oh = blocks_[static_cast<int>(SynapseType::OutputHidden)];

    // Hidden layer: immediate input, delayed hidden and output (state at t-1).
    for (std::size_t r = 0; r < h_.size(); ++r) {
        const auto ri = static_cast<Eigen::Index>(r);
        const double sum = row_dot(ih, ri, inputs.data()) + row_dot(hh, ri, h_.data()) + row_dot(oh, ri, o_.data());
        h_next_[r] = activate(model_, sum, h_[r]);
    }
    // Output layer: immediate hidden (at t), delayed output (at t-1).
    for (std::size_t r = 0; r < o_.size(); ++r) {
        const auto ri = static_cast<Eigen::Index>(r);
        const double sum = row_dot(ho, ri, h_next_.data()) + row_dot(oo, ri, o_.data());
        o_next_[r] = activate(model_, sum, o_[r]);
    }
    h_.swap(h_next_);
    o_.swap(o_next_);
    std::copy(o_.begin(), o_.end(), outputs.begin());
}

std::size_t Network::synapse_count() const {
    std::size_t n = 0;
    for (const auto& m : blocks_) n += static_cast<std::size_t>(m.nonZeros());
    return n;
}

std::size_t Network::synapse_count(SynapseType t) const {
    return static_cast<std::size_t>(blocks_[static_cast<int>(t)].nonZeros());
}

Eigen::MatrixXd Network::dense(SynapseType t) const { return Eigen::MatrixXd(matrix(t)); }

} // namespace cic::nn
