// Unit box <-> CPG weights (see cpg_encoding.hpp).
#include "cic/experiments/gait/cpg_encoding.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace cic::gait {

CpgEncoding::CpgEncoding(const sim::RobotSpec& robot, const nn::NeuralConfig& cfg, double step, Bounds b)
    : joints(robot.actuated().size()), edges(sim::cpg_neighbours(robot, cfg.cpg_hops)),
      weight_scale(cfg.cpg_weight_scale), feedback_scale(cfg.cpg_feedback), control_step(step), bounds(b) {
    if (joints == 0) throw std::invalid_argument("cpg encoding: the robot has no joints");
    if (!(weight_scale > 0) || !std::isfinite(weight_scale) || !(feedback_scale >= 0) || !std::isfinite(feedback_scale))
        throw std::invalid_argument("cpg encoding: need a finite weight scale > 0 and feedback scale >= 0");
    if (!(control_step > 0)) throw std::invalid_argument("cpg encoding: the control step must be > 0");
}

sim::CpgSpec CpgEncoding::decode(std::span<const double> x) const {
    if (x.size() != dimension())
        throw std::invalid_argument("cpg encoding: " + std::to_string(x.size()) + " parameters, expected " +
                                    std::to_string(dimension()));
    for (double v : x)
        if (!std::isfinite(v)) throw std::invalid_argument("cpg encoding: a parameter is not finite");
    auto signed_unit = [this](double v) { return 2.0 * to_unit(v, bounds) - 1.0; };
    sim::CpgSpec spec;
    spec.control_step = control_step;
    spec.edges = edges;
    std::size_t next = 0;
    for (std::size_t i = 0; i < joints; ++i) spec.self.push_back(weight_scale * signed_unit(x[next++]));
    for (std::size_t k = 0; k < edges.size(); ++k) spec.coupling.push_back(weight_scale * signed_unit(x[next++]));
    if (feedback_scale > 0)
        for (std::size_t i = 0; i < joints; ++i) spec.feedback.push_back(feedback_scale * signed_unit(x[next++]));
    return spec;
}

std::vector<double> CpgEncoding::in_box(std::span<const double> x) const {
    (void)decode(x);   // the same checks
    std::vector<double> out;
    for (double v : x) out.push_back(to_unit(v, bounds));   // every weight is read through to_unit
    return out;
}

} // namespace cic::gait
