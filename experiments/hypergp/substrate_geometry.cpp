#include "cic/experiments/hypergp/substrate_geometry.hpp"

#include <algorithm>
#include <stdexcept>

namespace cic::hypergp {

namespace {

// Maps [lo, hi] onto [-1, 1]; a degenerate range maps to 0. Written around the
// centre of the range (integers until the one division) so that cells mirrored
// about the centre get exactly opposite coordinates: symmetric robots keep
// bit-exact symmetric substrates.
double normalise(int v, int lo, int hi) {
    if (hi == lo) return 0.0;
    return static_cast<double>(2 * v - lo - hi) / static_cast<double>(hi - lo);
}

} // namespace

nn::Geometry substrate_geometry(const sim::RobotSpec& robot) { return substrate_geometry(robot, nn::NeuralConfig{}); }

nn::Geometry substrate_geometry(const sim::RobotSpec& robot, const nn::NeuralConfig& cfg) {
    robot.validate();
    const auto actuated = robot.actuated();
    if (actuated.empty())
        throw std::invalid_argument("substrate_geometry: robot '" + robot.name +
                                    "' has no actuated module, so the network would have no inputs or outputs");
    int x_lo = robot.modules[0].cell.x, x_hi = x_lo, y_lo = robot.modules[0].cell.y, y_hi = y_lo;
    for (const auto& m : robot.modules) {
        x_lo = std::min(x_lo, m.cell.x);
        x_hi = std::max(x_hi, m.cell.x);
        y_lo = std::min(y_lo, m.cell.y);
        y_hi = std::max(y_hi, m.cell.y);
    }
    // Absolute: measured from the centre module, so that mirrored cells get
    // exactly opposite coordinates here too, and a body's size moves nothing.
    const sim::Cell origin = robot.modules[static_cast<std::size_t>(robot.centre)].cell;
    const bool absolute = cfg.substrate_layout == nn::SubstrateLayout::Absolute;
    if (absolute && !(cfg.substrate_unit > 0.0))
        throw std::invalid_argument("substrate_geometry: substrateUnit must be > 0");
    auto point = [&](const sim::Cell& c) {
        if (absolute)
            return nn::Point{static_cast<double>(c.x - origin.x) / cfg.substrate_unit,
                             static_cast<double>(c.y - origin.y) / cfg.substrate_unit};
        return nn::Point{normalise(c.x, x_lo, x_hi), normalise(c.y, y_lo, y_hi)};
    };

    nn::Geometry g;
    for (int i : actuated) g.joints.push_back(point(robot.modules[static_cast<std::size_t>(i)].cell));
    for (const auto& m : robot.modules) {
        const auto p = point(m.cell);
        if (std::find(g.hidden.begin(), g.hidden.end(), p) == g.hidden.end()) g.hidden.push_back(p);
    }
    return g;
}

} // namespace cic::hypergp
