#include "cic/experiments/hypergp/neural_controller.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>
#include <string>

#include "cic/core/error.hpp"
#include "cic/nn/substrate.hpp"
#include "cic/experiments/hypergp/queries.hpp"
#include "cic/experiments/hypergp/substrate_geometry.hpp"

namespace cic::hypergp {

NeuralController::NeuralController(nn::Network network, nn::NeuronLayout layout, const nn::NeuralConfig& cfg)
    : network_(std::move(network)), layout_(std::move(layout)), cfg_(cfg) {
    if (cfg_.sample_average_count < 1)
        throw InputError("neural settings: sampleAverageCount must be >= 1, got " +
                         std::to_string(cfg_.sample_average_count));
    if (layout_.clock && !(cfg_.clock_period > 0.0))
        throw InputError("neural settings: clock_period must be > 0, got " + std::to_string(cfg_.clock_period));
    if (network_.input_count() != layout_.input.size() || network_.output_count() != layout_.output.size() ||
        network_.hidden_count() != layout_.hidden.size() || layout_.output.size() != layout_.joint_count)
        throw std::invalid_argument("NeuralController: network (" + std::to_string(network_.input_count()) + ", " +
                                    std::to_string(network_.hidden_count()) + ", " +
                                    std::to_string(network_.output_count()) + ") does not match the layout (" +
                                    std::to_string(layout_.input.size()) + ", " +
                                    std::to_string(layout_.hidden.size()) + ", " +
                                    std::to_string(layout_.output.size()) + ")");
    in_.assign(layout_.input.size(), 0.0);
    out_.assign(layout_.output.size(), 0.0);
    sum_.assign(layout_.output.size(), 0.0);
    command_.assign(layout_.output.size(), 0.0);
}

void NeuralController::reset(std::size_t joints) {
    if (joints != network_.output_count())
        throw std::invalid_argument("NeuralController: the robot has " + std::to_string(joints) +
                                    " actuated joints but the network has " +
                                    std::to_string(network_.output_count()) + " outputs");
    network_.reset();
    std::fill(sum_.begin(), sum_.end(), 0.0);
    std::fill(command_.begin(), command_.end(), 0.0);
    window_ = 0;
    record_ = ControlRecord{};
    record_.joints = joints;
}

void NeuralController::step(double t, std::span<const double> angles, std::span<double> desired) {
    if (desired.size() != out_.size())
        throw std::invalid_argument("NeuralController::step: " + std::to_string(desired.size()) +
                                    " desired angles for " + std::to_string(out_.size()) + " joints");
    nn::encode_inputs(layout_, cfg_, t, angles, in_);
    network_.step(in_, out_);
    for (std::size_t j = 0; j < out_.size(); ++j) sum_[j] += out_[j];
    if (++window_ == cfg_.sample_average_count) {
        const double scale = (std::numbers::pi / 2.0) / static_cast<double>(window_);
        for (std::size_t j = 0; j < out_.size(); ++j) {
            command_[j] = sum_[j] * scale;
            sum_[j] = 0.0;
        }
        window_ = 0;
    }
    std::copy(command_.begin(), command_.end(), desired.begin());
    if (recording_) {
        record_.times.push_back(t);
        record_.outputs.insert(record_.outputs.end(), out_.begin(), out_.end());
        record_.commands.insert(record_.commands.end(), command_.begin(), command_.end());
    }
}

NeuralController make_neural_controller(const sim::RobotSpec& robot, const tree::Forest& genotype,
                                        const nn::NeuralConfig& cfg) {
    nn::NeuralConfig c = cfg;
    if (c.evolve_clock) c.clock_period = 1.0 / evolved_frequency(genotype, c);
    auto layout = nn::make_neuron_layout(substrate_geometry(robot, c), c);
    auto network = nn::build_network(layout, genotype, c);
    return NeuralController(std::move(network), std::move(layout), c);
}

} // namespace cic::hypergp
