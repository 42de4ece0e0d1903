// A new controller built outside cic (docs/extending.md): `square`, HyperGP's
// gait substrate (each joint's amplitude, phase and offset asked of the trees,
// one evolved frequency) driving a softened square wave instead of a sine:
//   desired_j(t) = offset_j + amplitude_j tanh(4 sin(2 pi f t + phase_j)).
// Choose it with <Neural><substrate>square</substrate>, with any HyperGP-family
// type; `view`, `trace`, `assess` and `render` replay it as it was evaluated.
#include <cmath>
#include <memory>
#include <numbers>
#include <span>

#include "cic/experiments/hypergp/controller.hpp"
#include "cic/experiments/hypergp/gait_substrate.hpp"

namespace {

using namespace cic;

class SquareWave final : public sim::Controller {
public:
    explicit SquareWave(sim::GaitSpec spec) : spec_(std::move(spec)) {}
    void reset(std::size_t) override {}
    void step(double t, std::span<const double>, std::span<double> desired) override {
        const double w = 2 * std::numbers::pi * spec_.frequency;
        for (std::size_t j = 0; j < desired.size(); ++j) {
            if (j >= spec_.joints.size()) {
                desired[j] = 0.0;
                continue;
            }
            const sim::GaitJoint& g = spec_.joints[j];
            desired[j] = g.offset + g.amplitude * std::tanh(4 * std::sin(w * t + g.phase));
        }
    }

private:
    sim::GaitSpec spec_;
};

const hypergp::ControllerRegistrar registrar{{
    "square", "the gait substrate's parameters driving a softened square wave (examples/plugin)",
    [](const sim::RobotSpec& robot, const tree::Forest& genotype, const nn::NeuralConfig& cfg, double) {
        sim::GaitSpec spec = hypergp::gait_spec(robot, genotype, cfg);
        const std::size_t joints = spec.joints.size();
        // Outputs in [-1, 1] for traces and the oscillation penalty: commands / (pi/2).
        return std::unique_ptr<hypergp::Controller>(std::make_unique<hypergp::RecordedController>(
            std::make_unique<SquareWave>(std::move(spec)), std::numbers::pi / 2, joints));
    }}};

} // namespace
