// The two baseline controllers: constant and sine oscillator.
#include "cic/sim/controller.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace cic::sim {

void ConstantController::step(double, std::span<const double>, std::span<double> desired) {
    for (double& d : desired) d = angle_;
}

SineController::SineController(std::vector<SineJoint> params) : params_(std::move(params)) {
    if (params_.empty()) throw std::invalid_argument("SineController: no joint parameters");
    for (std::size_t i = 0; i < params_.size(); ++i) {
        const SineJoint& p = params_[i];
        if (!std::isfinite(p.amplitude) || !std::isfinite(p.frequency) || !std::isfinite(p.phase) ||
            p.frequency < 0)
            throw std::invalid_argument("SineController: joint " + std::to_string(i) +
                                        " needs finite amplitude and phase and frequency >= 0");
    }
}

void SineController::reset(std::size_t) {}

void SineController::step(double t, std::span<const double>, std::span<double> desired) {
    for (std::size_t j = 0; j < desired.size(); ++j) {
        const SineJoint& p = params_[std::min(j, params_.size() - 1)];
        desired[j] = p.amplitude * std::sin(2.0 * std::numbers::pi * p.frequency * t + p.phase);
    }
}

} // namespace cic::sim
