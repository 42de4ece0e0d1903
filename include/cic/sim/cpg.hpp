#pragma once
// A central pattern generator: one linear oscillator per joint, coupled to the
// joints near it in the body tree (the model of Revolve2's CPG brains; see
// docs/hypergp.md, "CPG substrate"). Joint i has two states (x_i, y_i):
//   dx_i/dt =  w_i y_i + sum_j w_ij x_j + g_i (theta_i / range - x_i)
//   dy_i/dt = -w_i x_i
// with w_ji = -w_ij (skew-symmetric couplings), theta_i the measured joint
// angle and g_i an optional feedback gain (0 = open loop). The states are
// integrated with one RK4 step per control step, holding theta fixed, and
// clipped to [-1, 1]; joint i is sent x_i * range. Without feedback the system
// matrix is skew-symmetric, so the state's norm is conserved (up to RK4's
// small dissipation and the clipping): a smooth, cyclic motion at angular
// frequencies set by the w's.
#include <cstddef>
#include <span>
#include <vector>

#include "cic/sim/controller.hpp"
#include "cic/sim/robot.hpp"

namespace cic::sim {

// A coupled pair of joints, as indices into RobotSpec::actuated() (a < b).
struct CpgEdge {
    int a = 0;
    int b = 0;
    bool operator==(const CpgEdge&) const = default;
};

// Pairs of joints whose modules are at most `max_hops` links apart in the
// attachment tree (Revolve2 uses 2), in (a, b) lexicographic order. Throws
// std::invalid_argument for max_hops < 1; cic::InputError for an invalid robot.
std::vector<CpgEdge> cpg_neighbours(const RobotSpec& robot, int max_hops);

struct CpgSpec {
    std::vector<double> self;       // w_i, rad/s, one per joint
    std::vector<CpgEdge> edges;
    std::vector<double> coupling;   // w_ab of each edge (w_ba = -w_ab), 1/s
    std::vector<double> feedback;   // g_i, 1/s; empty = open loop
    double range = 1.5707963267948966;   // rad: the command is x_i * range
    double initial = 0.7071067811865476; // every state starts here (Revolve2: sqrt(2)/2)
    double control_step = 0.0125;        // s: one RK4 step of this length per control step
};

// Throws std::invalid_argument: no joints, an edge out of range or with a >= b,
// sizes that disagree, a non-finite value, range <= 0, |initial| > 1 or
// control_step <= 0.
void validate(const CpgSpec& spec);

class CpgController final : public Controller {
public:
    explicit CpgController(CpgSpec spec);   // validates
    // Throws std::invalid_argument unless joints == spec.self.size().
    void reset(std::size_t joints) override;
    void step(double t, std::span<const double> angles, std::span<double> desired) override;

    const CpgSpec& spec() const { return spec_; }
    // The oscillator states after the last step, x then y, for tests and traces.
    std::span<const double> state() const { return state_; }

private:
    void derivative(std::span<const double> s, std::span<const double> angles, std::span<double> ds) const;

    CpgSpec spec_;
    std::vector<double> state_, k1_, k2_, k3_, k4_, tmp_;
};

} // namespace cic::sim
