// Genotype -> open-loop gait parameters (see gait_substrate.hpp).
#include "cic/experiments/hypergp/gait_substrate.hpp"

#include <numbers>
#include <stdexcept>
#include <vector>

#include "cic/experiments/hypergp/queries.hpp"
#include "cic/experiments/hypergp/substrate_geometry.hpp"

namespace cic::hypergp {

sim::GaitSpec gait_spec(const sim::RobotSpec& robot, const tree::Forest& genotype, const nn::NeuralConfig& cfg) {
    if (genotype.empty()) throw std::invalid_argument("gait substrate: empty genotype (no trees)");
    constexpr double pi = std::numbers::pi;
    const nn::Geometry g = substrate_geometry(robot);
    const std::size_t n = g.joints.size(), trees = genotype.size();
    std::vector<Query> qs;
    for (std::size_t i = 0; i < n; ++i) {
        qs.push_back({0 % trees, g.joints[i], kAmplitudePoint});
        qs.push_back({1 % trees, g.joints[i], kPhasePoint});
        qs.push_back({2 % trees, g.joints[i], kOffsetPoint});
    }
    const std::vector<double> v = ask(genotype, cfg, qs);
    sim::GaitSpec spec;
    spec.frequency = evolved_frequency(genotype, cfg);
    spec.joints.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        spec.joints[i].amplitude = pi / 2 * unit(v[3 * i]);
        spec.joints[i].phase = pi * squash(v[3 * i + 1]);
        spec.joints[i].offset = pi / 2 * squash(v[3 * i + 2]);
    }
    return spec;
}

} // namespace cic::hypergp
