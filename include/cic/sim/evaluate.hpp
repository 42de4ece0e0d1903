#pragma once
// One evaluation: build a world for the robot, run the controller from
// sample_from to sample_to, and compute fitness (thesis eq. 7.1).
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cic/sim/config.hpp"
#include "cic/sim/controller.hpp"
#include "cic/sim/recording.hpp"
#include "cic/sim/robot.hpp"

namespace cic::sim {

struct EvalOptions {
    double record_fps = 0.0;        // > 0: record frames at this rate
    bool record_trace = false;      // record a TraceRow per control step
    bool record_ground = false;     // count, per module, the physics steps it touches the ground
                                    // (with record_trace, also each row's foot contacts)
};

struct EvalResult {
    double fitness = 0.0;           // |t_p - s_p| + (t_z - s_z), or failure_fitness
    bool failed = false;            // physics blow-up
    std::string failure;            // why, when failed
    std::array<double, 3> start{};  // centre position at delayed_start
    std::array<double, 3> end{};    // centre position at sample_to
    double simulated_seconds = 0.0;
    long steps = 0;                 // physics steps taken
    long ground_contacts = 0;       // contact points summed over the physics steps
    long self_contacts = 0;         // between bodies of the robot (selfCollision)
    int max_ground_contacts = 0;    // most in one step
    int max_self_contacts = 0;
    double max_ground_depth = 0.0;  // deepest contact with the ground, m (how far parts sink)
    double max_body_speed = 0.0;    // fastest body at the end of any physics step, m/s
    std::optional<Recording> recording;
    std::vector<TraceRow> trace;
    // With record_ground: per module, the physics steps from the delayed start
    // on in which any of its parts touched the ground, out of `ground_steps`.
    std::vector<long> module_ground_steps;
    long ground_steps = 0;
};

// Eq. 7.1's two terms of an evaluation, m: the walk along the robot's preferred
// axis, |t_p - s_p|, and the elevation its centre gained, t_z - s_z. Their sum
// is the fitness of a plain evaluation.
std::pair<double, double> walk_terms(const RobotSpec& robot, const EvalResult& result);

// The end modules of the robot's branches (modules no other module attaches
// to, the centre excepted), in module order: a legged robot's feet, a snake's
// two ends. The duty factor of each is what its ground steps are counted for.
std::vector<int> branch_ends(const RobotSpec& robot);

// Names for people: each actuated joint's module (controller order) and each
// branch end's (branch_ends order); a module without a name is "m<index>".
std::vector<std::string> joint_names(const RobotSpec& robot);
std::vector<std::string> foot_names(const RobotSpec& robot);

// The duty factor of each branch end (branch_ends order): the share of the
// physics steps from the delayed start on in which it touched the ground, in
// [0, 1]. The behaviour descriptor of Cully et al. 2015, shown by `cic assess`
// and the descriptor of MAP-Elites archives. Empty unless the evaluation
// recorded the ground (EvalOptions::record_ground).
std::vector<double> duty_factors(const RobotSpec& robot, const EvalResult& result);

// Behaviour descriptors (Descriptor, config.hpp):
std::string to_string(Descriptor d);             // "none", "duty-factor", "omni"
Descriptor descriptor_from(const std::string& name);   // throws std::invalid_argument
// Its values for one evaluation: empty for None. DutyFactor needs the ground
// recorded (EvalOptions::record_ground; see needs_ground).
std::vector<double> descriptor_of(Descriptor d, const RobotSpec& robot, const EvalResult& result);
inline bool needs_ground(Descriptor d) { return d == Descriptor::DutyFactor; }

// Deterministic: resets ODE's global random state (dRandSetSeed) before
// building the world, and the world uses its own self-threaded implementation.
// Throws std::invalid_argument for invalid config (e.g. step <= 0, or a physics
// step above kMaxStablePhysicsStep without allow_coarse_step).
EvalResult evaluate(const RobotSpec& robot, Controller& controller, const SimConfig& cfg,
                    const EvalOptions& options = {});

} // namespace cic::sim
