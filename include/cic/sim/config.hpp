#pragma once
// Plain simulator settings with the thesis's and the reference simulator's defaults.
#include <limits>

namespace cic::sim {

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
    double failure_fitness = -1e3; // fitness given to a failed evaluation
};

} // namespace cic::sim
