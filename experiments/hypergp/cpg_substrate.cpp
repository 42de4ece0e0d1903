// Genotype -> CPG weights (see cpg_substrate.hpp).
#include "cic/experiments/hypergp/cpg_substrate.hpp"

#include <stdexcept>
#include <vector>

#include "cic/experiments/hypergp/queries.hpp"
#include "cic/experiments/hypergp/substrate_geometry.hpp"

namespace cic::hypergp {

sim::CpgSpec cpg_spec(const sim::RobotSpec& robot, const tree::Forest& genotype, const nn::NeuralConfig& cfg,
                      double control_step) {
    if (genotype.empty()) throw std::invalid_argument("cpg substrate: empty genotype (no trees)");
    const nn::Geometry g = substrate_geometry(robot, cfg);
    const std::size_t n = g.joints.size();
    sim::CpgSpec spec;
    spec.control_step = control_step;
    spec.edges = sim::cpg_neighbours(robot, cfg.cpg_hops);
    const bool feedback = cfg.cpg_feedback > 0.0;
    const std::size_t feedback_tree = 1 % genotype.size();

    std::vector<Query> qs;
    for (std::size_t i = 0; i < n; ++i) qs.push_back({0, g.joints[i], g.joints[i]});
    for (const sim::CpgEdge& e : spec.edges)
        qs.push_back({0, g.joints[static_cast<std::size_t>(e.a)], g.joints[static_cast<std::size_t>(e.b)]});
    if (feedback)
        for (std::size_t i = 0; i < n; ++i) qs.push_back({feedback_tree, g.joints[i], kFeedbackPoint});
    const std::vector<double> v = ask(genotype, cfg, qs);

    std::size_t next = 0;
    for (std::size_t i = 0; i < n; ++i) spec.self.push_back(cfg.cpg_weight_scale * squash(v[next++]));
    for (std::size_t k = 0; k < spec.edges.size(); ++k) spec.coupling.push_back(cfg.cpg_weight_scale * squash(v[next++]));
    if (feedback)
        for (std::size_t i = 0; i < n; ++i) spec.feedback.push_back(cfg.cpg_feedback * squash(v[next++]));
    sim::validate(spec);
    return spec;
}

} // namespace cic::hypergp
