#pragma once
// The substrate network driving a robot (thesis 6.2.2, 7.3.2.1).
//
// Each control step: inputs = joint angles / (pi/2) (+ bias, clock), one
// network step, outputs o in [-1, 1]. With sampleAverageCount n the command
// is down-sampled: it is updated on every n-th step (steps n-1, 2n-1, ...,
// counted from reset) to the mean of the last n outputs, and held in between;
// before the first update it is 0. n = 1 means command = output every step.
// Desired angle = command * pi/2.
#include <cstddef>
#include <span>
#include <vector>

#include "cic/nn/config.hpp"
#include "cic/nn/geometry.hpp"
#include "cic/nn/network.hpp"
#include "cic/experiments/hypergp/controller.hpp"
#include "cic/sim/robot.hpp"
#include "cic/tree/tree.hpp"

namespace cic::hypergp {

class NeuralController final : public Controller {
public:
    // Throws cic::InputError for sample_average_count < 1 (or clock inputs with
    // clock_period <= 0) and std::invalid_argument if network and layout disagree.
    NeuralController(nn::Network network, nn::NeuronLayout layout, const nn::NeuralConfig& cfg);

    // reset() throws std::invalid_argument unless joints == the network's output count.
    void reset(std::size_t joints) override;
    void step(double t, std::span<const double> angles, std::span<double> desired) override;

    void set_recording(bool on) override { recording_ = on; }
    const ControlRecord& record() const override { return record_; }
    std::size_t connections() const override { return network_.synapse_count(); }
    const nn::Network& network() const { return network_; }
    const nn::NeuronLayout& layout() const { return layout_; }
    double clock_period() const { return cfg_.clock_period; }   // s (evolved or from the settings)

private:
    nn::Network network_;
    nn::NeuronLayout layout_;
    nn::NeuralConfig cfg_;
    std::vector<double> in_, out_, sum_, command_;
    int window_ = 0;               // outputs summed since the last command update
    bool recording_ = false;
    ControlRecord record_;
};

// Genotype + robot -> ready controller: substrate_geometry, make_neuron_layout,
// build_network; with cfg.evolve_clock the clock period is 1 / the evolved
// frequency (queries.hpp) instead of cfg.clock_period.
NeuralController make_neural_controller(const sim::RobotSpec& robot, const tree::Forest& genotype,
                                        const nn::NeuralConfig& cfg);

} // namespace cic::hypergp
