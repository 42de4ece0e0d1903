#pragma once
// Simulator settings: the plain struct with the thesis's and the reference
// simulator's defaults, and the one description of its fields (name, settings
// key, range, meaning) that the settings table, the worker job text and
// validation all read.
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace cic::sim {

// A behaviour descriptor a MAP-Elites archive keeps its elites by (evaluate.hpp
// computes it):
//   DutyFactor  each branch end's duty factor (Cully et al. 2015), in [0, 1];
//   Omni        the centre's displacement (x, y) from the delayed start to the
//               end, in metres (QDax's "omni" descriptor: where it went).
enum class Descriptor { None, DutyFactor, Omni };

// The longest physics step (sample_step / step_divider) that cic trusts, s.
// Measured (docs/simulator.md, "Step size"): up to the thesis's own 0.5 s / 20 =
// 0.025 s the R1 gaits keep their fitness within a few per cent of a 2.5 ms
// reference; at 0.05 s parts sink deep into the ground, and coarser steps give
// fitness that no real robot could walk. Longer steps need allow_coarse_step.
inline constexpr double kMaxStablePhysicsStep = 0.025;

// Simulator.collisionSpace. Simple: ODE's simple space, every pair of geoms
// tested (cost quadratic in modules; the thesis's and the golden runs' bits).
// Sweep: the same simple space, but the robot's pairs are found by cic's
// sort-and-sweep along the robot's longest axis and then put into the order
// the simple space reports them in, so the contacts reach QuickStep in the
// same order: simple's bits at a cost about linear in modules. Sap: ODE's
// sweep-and-prune space, pairs put into the order of the robot's geoms (other
// bits than simple's once two robot bodies touch).
inline constexpr int kCollisionSimple = 0;
inline constexpr int kCollisionSweep = 1;
inline constexpr int kCollisionSap = 2;

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
    // How the robot's geoms find the pairs to test for contact (docs/simulator.md,
    // "Collision space"): kCollisionSimple, kCollisionSweep or kCollisionSap.
    int collision_space = kCollisionSweep;   // simple's bits, about linear in modules (issue 55)

    double physics_step() const { return sample_step / step_divider; }
};

// What one SimConfig field is. Ranges are inclusive unless min_exclusive;
// doubles must be finite unless allow_inf (NaN never). Bools have no range.
struct FieldSpec {
    std::string_view name;   // member and worker-job-text name
    std::string_view key;    // settings key in <Simulator> (the thesis's name where it has one)
    std::string_view doc;    // one line for --help, docs and the schema
    double min = -std::numeric_limits<double>::max();
    double max = std::numeric_limits<double>::max();
    bool min_exclusive = false;
    bool allow_inf = false;
};

// Calls f(spec, member) for every field of c, in settings-file order.
// Config is SimConfig or const SimConfig.
template <class Config, class F>
    requires std::is_same_v<std::remove_const_t<Config>, SimConfig>
void for_each_field(Config& c, F&& f) {
    constexpr double kHuge = std::numeric_limits<double>::max();
    f(FieldSpec{"sample_from", "sample_from", "Simulation start time, s", 0.0, kHuge}, c.sample_from);
    f(FieldSpec{"sample_step", "sample_step",
                "Control step, s: how often the network computes new outputs (thesis 7.2.3)", 0.0, kHuge, true},
      c.sample_step);
    f(FieldSpec{"sample_to", "sample_to", "Simulation stop time, s", 0.0, kHuge, true}, c.sample_to);
    f(FieldSpec{"delayed_start", "delayed_start",
                "Time at which the start position is taken for the fitness, s (thesis 7.1.2)", 0.0, kHuge},
      c.delayed_start);
    f(FieldSpec{"step_divider", "extraTimeStepDivider",
                "Physics substeps per control step (physics dt = sample_step / divider)", 1, 10000},
      c.step_divider);
    f(FieldSpec{"gravity", "gravity", "Gravity, m/s^2 (pointing down)", 0.0, 1000.0}, c.gravity);
    f(FieldSpec{"erp", "erp", "ODE error reduction parameter", 0.0, 1.0}, c.erp);
    f(FieldSpec{"cfm", "cfm", "ODE constraint force mixing", 0.0, 1.0}, c.cfm);
    f(FieldSpec{"quickstep_iterations", "quickStepIterations", "ODE QuickStep iterations", 1, 10000},
      c.quickstep_iterations);
    f(FieldSpec{"friction", "friction", "Contact friction mu; inf = infinite", 0.0, kHuge, false, true}, c.friction);
    f(FieldSpec{"soft_cfm", "softCfm", "Contact softness (ODE soft CFM)", 0.0, 1.0}, c.soft_cfm);
    f(FieldSpec{"bounce", "bounce", "Contact restitution", 0.0, 1.0}, c.bounce);
    f(FieldSpec{"max_contacts", "maxContacts", "Contact points per colliding geom pair", 1, 64}, c.max_contacts);
    f(FieldSpec{"joint_gain", "jointGain", "Joint P-controller gain: velocity = gain * (angle - desired)", -1e6, 1e6},
      c.joint_gain);
    f(FieldSpec{"max_motor_force", "maxMotorForce", "Maximum joint motor force, N", 0.0, kHuge, true},
      c.max_motor_force);
    f(FieldSpec{"blowup_bound", "blowupBound", "A position or velocity beyond this counts as a physics blow-up", 0.0,
                kHuge, true},
      c.blowup_bound);
    f(FieldSpec{"max_body_speed", "maxBodySpeed",
                "A body faster than this (m/s) counts as a physics blow-up (failed evaluation)", 0.0, kHuge, true},
      c.max_body_speed);
    f(FieldSpec{"failure_fitness", "failureFitness", "Fitness given to a failed (blown-up) evaluation"},
      c.failure_fitness);
    f(FieldSpec{"self_collision", "selfCollision",
                "Bodies of the robot collide with each other (except those joined by a hinge)"},
      c.self_collision);
    f(FieldSpec{"allow_coarse_step", "allowCoarseStep",
                "Accept a physics step sample_step / extraTimeStepDivider above the stability bound "
                "(docs/simulator.md); results are then physics artefacts"},
      c.allow_coarse_step);
    f(FieldSpec{"collision_space", "collisionSpace",
                "How robot geoms find contact pairs: 0 simple (all pairs, quadratic in modules), 1 sweep (cic's "
                "sort-and-sweep, about linear, simple's bits: the default), 2 ODE's sweep-and-prune (about linear, "
                "pairs in geom order); docs/simulator.md",
                0, 2},
      c.collision_space);
}

// One reason a SimConfig cannot run, naming the fields (FieldSpec::name) involved.
struct ConfigProblem {
    std::vector<std::string_view> fields;
    std::string why;
};

// Every field outside its FieldSpec range, then every cross-field rule broken
// (start before stop, delayed_start in [sample_from, sample_to), control step
// within the simulated time, physics step within kMaxStablePhysicsStep unless
// allow_coarse_step). Empty = the config runs.
std::vector<ConfigProblem> config_problems(const SimConfig& c);

} // namespace cic::sim
