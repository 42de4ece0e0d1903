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

GaitController::GaitController(GaitSpec spec) : spec_(std::move(spec)) {
    if (spec_.joints.empty()) throw std::invalid_argument("GaitController: no joint parameters");
    if (!std::isfinite(spec_.frequency) || spec_.frequency < 0)
        throw std::invalid_argument("GaitController: the frequency must be finite and >= 0");
    for (std::size_t i = 0; i < spec_.joints.size(); ++i) {
        const GaitJoint& j = spec_.joints[i];
        for (double v : {j.amplitude, j.phase, j.offset, j.amplitude2, j.phase2})
            if (!std::isfinite(v))
                throw std::invalid_argument("GaitController: joint " + std::to_string(i) + " has a non-finite parameter");
    }
}

void GaitController::step(double t, std::span<const double>, std::span<double> desired) {
    const double w = 2.0 * std::numbers::pi * spec_.frequency * t;
    for (std::size_t j = 0; j < desired.size(); ++j) {
        if (j >= spec_.joints.size()) {
            desired[j] = 0.0;
            continue;
        }
        const GaitJoint& p = spec_.joints[j];
        desired[j] = p.offset + p.amplitude * std::sin(w + p.phase) + p.amplitude2 * std::sin(2.0 * w + p.phase2);
    }
}

std::vector<SineJoint> tripod_gait(int legs, int joints_per_leg, double amplitude, double frequency) {
    if (legs < 1 || joints_per_leg < 1) throw std::invalid_argument("tripod_gait: legs and joints_per_leg must be >= 1");
    const double pi = std::numbers::pi;
    std::vector<SineJoint> gait;
    for (int leg = 0; leg < legs; ++leg) {
        const int row = leg / 2, side = leg % 2;
        for (int k = 0; k < joints_per_leg; ++k)
            gait.push_back({amplitude, frequency, pi * ((row + side) % 2) + (k == 0 ? 0.0 : pi / 2)});
    }
    return gait;
}

} // namespace cic::sim
