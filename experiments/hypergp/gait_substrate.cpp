// Genotype -> open-loop gait parameters (see gait_substrate.hpp).
#include "cic/experiments/hypergp/gait_substrate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <stdexcept>
#include <vector>

#include "cic/experiments/hypergp/queries.hpp"
#include "cic/experiments/hypergp/substrate_geometry.hpp"

namespace cic::hypergp {

namespace {

// What the trees say at each joint, before the ranges scale it: u_a in [0, 1],
// t_p and s_o in [-1, 1] (s_o with the direct offset added and clamped).
struct Units {
    std::vector<double> amplitude, phase, offset;
};

Units units(const sim::RobotSpec& robot, const tree::Forest& genotype, const nn::NeuralConfig& cfg,
            std::span<const double> offsets) {
    if (genotype.empty()) throw std::invalid_argument("gait substrate: empty genotype (no trees)");
    const nn::Geometry g = substrate_geometry(robot, cfg);
    const std::size_t n = g.joints.size(), trees = genotype.size();
    if (!offsets.empty() && offsets.size() != n)
        throw std::invalid_argument("gait substrate: " + std::to_string(offsets.size()) + " direct offsets for " +
                                    std::to_string(n) + " joints");
    for (double d : offsets)
        if (!std::isfinite(d)) throw std::invalid_argument("gait substrate: a direct offset is not finite");
    std::vector<Query> qs;
    for (std::size_t i = 0; i < n; ++i) {
        qs.push_back({0 % trees, g.joints[i], kAmplitudePoint});
        qs.push_back({1 % trees, g.joints[i], kPhasePoint});
        qs.push_back({2 % trees, g.joints[i], kOffsetPoint});
    }
    const std::vector<double> v = ask(genotype, cfg, qs);
    Units u;
    for (std::size_t i = 0; i < n; ++i) {
        u.amplitude.push_back(unit(v[3 * i]));
        u.phase.push_back(squash(v[3 * i + 1]));
        u.offset.push_back(offsets.empty() ? squash(v[3 * i + 2])
                                           : std::clamp(squash(v[3 * i + 2]) + offsets[i], -1.0, 1.0));
    }
    return u;
}

} // namespace

sim::GaitSpec gait_spec(const sim::RobotSpec& robot, const tree::Forest& genotype, const nn::NeuralConfig& cfg,
                        std::span<const double> offsets) {
    constexpr double pi = std::numbers::pi;
    const Units u = units(robot, genotype, cfg, offsets);
    sim::GaitSpec spec;
    spec.frequency = evolved_frequency(genotype, cfg);
    spec.joints.resize(u.amplitude.size());
    for (std::size_t i = 0; i < spec.joints.size(); ++i) {
        spec.joints[i].amplitude = pi / 2 * u.amplitude[i];
        spec.joints[i].phase = pi * u.phase[i];
        spec.joints[i].offset = pi / 2 * u.offset[i];
    }
    return spec;
}

std::vector<double> gait_box_point(const sim::RobotSpec& robot, const tree::Forest& genotype,
                                   const nn::NeuralConfig& cfg, std::span<const double> offsets) {
    const Units u = units(robot, genotype, cfg, offsets);
    std::vector<double> x{evolved_frequency_unit(genotype, cfg)};
    for (std::size_t i = 0; i < u.amplitude.size(); ++i) {
        // Halving is exact: the centred layout doubles them back (gait/encoding.hpp).
        x.push_back(u.amplitude[i]);
        x.push_back(u.phase[i] / 2);
        x.push_back(u.offset[i] / 2);
    }
    return x;
}

} // namespace cic::hypergp
