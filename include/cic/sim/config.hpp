#pragma once
// Plain simulator settings with the thesis's and the reference simulator's defaults.
#include <limits>

namespace cic::sim {

// The longest physics step (sample_step / step_divider) that cic trusts, s.
// Measured (docs/simulator.md, "Step size"): up to the thesis's own 0.5 s / 20 =
// 0.025 s the R1 gaits keep their fitness within a few per cent of a 2.5 ms
// reference; at 0.05 s parts sink deep into the ground, and coarser steps give
// fitness that no real robot could walk. Longer steps need allow_coarse_step.
inline constexpr double kMaxStablePhysicsStep = 0.025;

struct SimConfig {
    double sample_from = 0.0;      // s
    double sample_step = 0.0125;   // control step, s
    double sample_to = 15.0;       // s
    double delayed_start = 2.0;    // s; fitness start point is taken here
    int step_divider = 1;          // extraTimeStepDivider: physics dt = sample_step / divider
    double gravity = 9.81;
    double erp = 0.8;
    double cfm = 1e-4;
    int quickstep_iterations = 20;
    double friction = std::numeric_limits<double>::infinity();  // contact mu; inf = dInfinity
    double soft_cfm = 1e-4;
    double bounce = 0.1;
    int max_contacts = 4;          // per geom pair
    double joint_gain = -1.0;      // P-controller: velocity = gain * (angle - desired)
    double max_motor_force = 200.0;
    double blowup_bound = 1e4;     // |position| or |velocity| past this = physics blow-up
    double max_body_speed = 30.0;  // m/s; a body faster than this = physics blow-up
    double failure_fitness = -1e3; // fitness given to a failed evaluation
    bool self_collision = true;    // bodies of the robot collide with each other
    bool allow_coarse_step = false;   // accept a physics step above kMaxStablePhysicsStep

    double physics_step() const { return sample_step / step_divider; }
};

} // namespace cic::sim
