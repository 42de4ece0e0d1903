// The CPG controller and its neighbourhood (see cpg.hpp).
#include "cic/sim/cpg.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

namespace cic::sim {

namespace {

// parent[i] in the attachment tree (-1 for the centre); the robot is valid.
std::vector<int> parents(const RobotSpec& robot) {
    std::map<std::tuple<int, int, int>, int> at;
    for (std::size_t i = 0; i < robot.modules.size(); ++i) {
        const Cell c = robot.modules[i].cell;
        at.emplace(std::tuple{c.x, c.y, c.z}, static_cast<int>(i));
    }
    std::vector<int> parent(robot.modules.size(), -1);
    for (std::size_t i = 0; i < robot.modules.size(); ++i) {
        if (static_cast<int>(i) == robot.centre) continue;
        const Cell c = neighbour(robot.modules[i].cell, robot.modules[i].attach);
        parent[i] = at.at(std::tuple{c.x, c.y, c.z});
    }
    return parent;
}

// Links between modules a and b in the tree.
int tree_distance(const std::vector<int>& parent, int a, int b) {
    std::map<int, int> up;   // ancestor of a -> its distance from a
    for (int v = a, d = 0; v >= 0; v = parent[static_cast<std::size_t>(v)], ++d) up.emplace(v, d);
    for (int v = b, d = 0; v >= 0; v = parent[static_cast<std::size_t>(v)], ++d)
        if (auto it = up.find(v); it != up.end()) return it->second + d;
    return -1;   // unreachable in a valid robot
}

[[noreturn]] void bad(const std::string& why) { throw std::invalid_argument("CPG: " + why); }

} // namespace

std::vector<CpgEdge> cpg_neighbours(const RobotSpec& robot, int max_hops) {
    if (max_hops < 1) bad("the neighbourhood must be at least 1 hop, got " + std::to_string(max_hops));
    robot.validate();
    const std::vector<int> parent = parents(robot);
    const std::vector<int> joints = robot.actuated();
    std::vector<CpgEdge> edges;
    for (std::size_t a = 0; a < joints.size(); ++a)
        for (std::size_t b = a + 1; b < joints.size(); ++b)
            if (tree_distance(parent, joints[a], joints[b]) <= max_hops)
                edges.push_back({static_cast<int>(a), static_cast<int>(b)});
    return edges;
}

void validate(const CpgSpec& s) {
    const std::size_t n = s.self.size();
    if (n == 0) bad("no joints");
    if (s.coupling.size() != s.edges.size())
        bad(std::to_string(s.edges.size()) + " edges but " + std::to_string(s.coupling.size()) + " coupling weights");
    if (!s.feedback.empty() && s.feedback.size() != n)
        bad(std::to_string(n) + " joints but " + std::to_string(s.feedback.size()) + " feedback gains");
    for (const CpgEdge& e : s.edges)
        if (e.a < 0 || e.b <= e.a || static_cast<std::size_t>(e.b) >= n)
            bad("edge (" + std::to_string(e.a) + ", " + std::to_string(e.b) + ") is not a pair a < b of the " +
                std::to_string(n) + " joints");
    for (const auto* v : {&s.self, &s.coupling, &s.feedback})
        for (double w : *v)
            if (!std::isfinite(w)) bad("a weight is not finite");
    if (!(s.range > 0) || !std::isfinite(s.range)) bad("the range must be finite and > 0");
    if (!(std::abs(s.initial) <= 1)) bad("the initial state must be in [-1, 1]");
    if (!(s.control_step > 0) || !std::isfinite(s.control_step)) bad("the control step must be finite and > 0");
}

CpgController::CpgController(CpgSpec spec) : spec_(std::move(spec)) {
    validate(spec_);
    const std::size_t states = 2 * spec_.self.size();
    for (auto* v : {&state_, &k1_, &k2_, &k3_, &k4_, &tmp_}) v->assign(states, 0.0);
    reset(spec_.self.size());
}

void CpgController::reset(std::size_t joints) {
    if (joints != spec_.self.size())
        bad("the robot has " + std::to_string(joints) + " joints but the CPG has " +
            std::to_string(spec_.self.size()) + " oscillators");
    std::fill(state_.begin(), state_.end(), spec_.initial);
}

void CpgController::derivative(std::span<const double> s, std::span<const double> angles,
                               std::span<double> ds) const {
    const std::size_t n = spec_.self.size();
    const auto x = s.subspan(0, n), y = s.subspan(n, n);
    for (std::size_t i = 0; i < n; ++i) {
        ds[i] = spec_.self[i] * y[i];
        ds[n + i] = -spec_.self[i] * x[i];
    }
    for (std::size_t k = 0; k < spec_.edges.size(); ++k) {
        const auto a = static_cast<std::size_t>(spec_.edges[k].a), b = static_cast<std::size_t>(spec_.edges[k].b);
        ds[a] += spec_.coupling[k] * x[b];
        ds[b] -= spec_.coupling[k] * x[a];
    }
    if (!spec_.feedback.empty())
        for (std::size_t i = 0; i < n; ++i) ds[i] += spec_.feedback[i] * (angles[i] / spec_.range - x[i]);
}

void CpgController::step(double, std::span<const double> angles, std::span<double> desired) {
    const std::size_t n = spec_.self.size();
    if (angles.size() != n || desired.size() != n)
        bad("step: " + std::to_string(angles.size()) + " angles and " + std::to_string(desired.size()) +
            " desired angles for " + std::to_string(n) + " oscillators");
    // The command of this step comes from the current state; then one RK4
    // step advances the oscillators to the next control step.
    for (std::size_t i = 0; i < n; ++i) desired[i] = state_[i] * spec_.range;
    const double h = spec_.control_step;
    auto stage = [&](const std::vector<double>& k, double f) {
        for (std::size_t i = 0; i < tmp_.size(); ++i) tmp_[i] = state_[i] + f * h * k[i];
    };
    derivative(state_, angles, k1_);
    stage(k1_, 0.5);
    derivative(tmp_, angles, k2_);
    stage(k2_, 0.5);
    derivative(tmp_, angles, k3_);
    stage(k3_, 1.0);
    derivative(tmp_, angles, k4_);
    for (std::size_t i = 0; i < state_.size(); ++i)
        state_[i] = std::clamp(state_[i] + h / 6.0 * (k1_[i] + 2.0 * k2_[i] + 2.0 * k3_[i] + k4_[i]), -1.0, 1.0);
}

} // namespace cic::sim
