// Genotype -> the controller Neural.substrate names (see controller.hpp).
#include "cic/experiments/hypergp/controller.hpp"

#include <numbers>
#include <stdexcept>

#include "cic/sim/cpg.hpp"
#include "cic/experiments/hypergp/cpg_substrate.hpp"
#include "cic/experiments/hypergp/gait_substrate.hpp"
#include "cic/experiments/hypergp/neural_controller.hpp"

namespace cic::hypergp {

RecordedController::RecordedController(std::unique_ptr<sim::Controller> inner, double scale, std::size_t connections)
    : inner_(std::move(inner)), scale_(scale), connections_(connections) {
    if (!inner_) throw std::invalid_argument("RecordedController: no controller");
    if (!(scale_ > 0)) throw std::invalid_argument("RecordedController: the scale must be > 0");
}

void RecordedController::reset(std::size_t joints) {
    inner_->reset(joints);
    record_ = ControlRecord{};
    record_.joints = joints;
}

void RecordedController::step(double t, std::span<const double> angles, std::span<double> desired) {
    inner_->step(t, angles, desired);
    if (!recording_) return;
    record_.times.push_back(t);
    for (double d : desired) record_.outputs.push_back(d / scale_);
    record_.commands.insert(record_.commands.end(), desired.begin(), desired.end());
}

std::unique_ptr<Controller> make_controller(const sim::RobotSpec& robot, const tree::Forest& genotype,
                                            const nn::NeuralConfig& cfg, double control_step) {
    constexpr double half_pi = std::numbers::pi / 2;
    switch (cfg.substrate) {
    case nn::Substrate::Network:
        return std::make_unique<NeuralController>(make_neural_controller(robot, genotype, cfg));
    case nn::Substrate::Cpg: {
        sim::CpgSpec spec = cpg_spec(robot, genotype, cfg, control_step);
        const std::size_t pairs = spec.edges.size();
        const double range = spec.range;
        return std::make_unique<RecordedController>(std::make_unique<sim::CpgController>(std::move(spec)), range,
                                                    pairs);
    }
    case nn::Substrate::Gait: {
        sim::GaitSpec spec = gait_spec(robot, genotype, cfg);
        const std::size_t joints = spec.joints.size();
        return std::make_unique<RecordedController>(std::make_unique<sim::GaitController>(std::move(spec)), half_pi,
                                                    joints);
    }
    }
    throw std::invalid_argument("make_controller: unknown substrate");
}

} // namespace cic::hypergp
