// One deterministic evaluation: world, control loop, fitness (thesis eq. 7.1).
#include "cic/sim/evaluate.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "world.hpp"

namespace cic::sim {

namespace {

void check_config(const SimConfig& c, const EvalOptions& o) {
    auto fail = [](const std::string& what) { throw std::invalid_argument("SimConfig: " + what); };
    auto finite = [](double v) { return std::isfinite(v); };
    if (!finite(c.sample_step) || c.sample_step <= 0) fail("sample_step must be > 0");
    if (!finite(c.sample_from) || !finite(c.sample_to) || c.sample_to <= c.sample_from)
        fail("sample_to must be after sample_from");
    if (!finite(c.delayed_start) || c.delayed_start < c.sample_from || c.delayed_start > c.sample_to)
        fail("delayed_start must lie in [sample_from, sample_to]");
    if ((c.sample_to - c.sample_from) / c.sample_step > 1e9) fail("too many control steps");
    if (c.step_divider < 1) fail("step_divider must be >= 1");
    if (c.physics_step() > kMaxStablePhysicsStep && !c.allow_coarse_step)
        fail("physics step sample_step / step_divider = " + std::to_string(c.physics_step()) + " s is above " +
             std::to_string(kMaxStablePhysicsStep) + " s (allow_coarse_step is off)");
    if (c.quickstep_iterations < 1) fail("quickstep_iterations must be >= 1");
    if (c.max_contacts < 1 || c.max_contacts > 64) fail("max_contacts must be in [1, 64]");
    if (!finite(c.gravity) || !finite(c.erp) || !finite(c.cfm) || c.erp < 0 || c.erp > 1 || c.cfm < 0)
        fail("gravity must be finite, erp in [0, 1], cfm >= 0");
    if (std::isnan(c.friction) || c.friction < 0) fail("friction must be >= 0 (inf allowed)");
    if (!finite(c.soft_cfm) || c.soft_cfm < 0 || !finite(c.bounce) || c.bounce < 0 || c.bounce > 1)
        fail("soft_cfm must be >= 0 and bounce in [0, 1]");
    if (!finite(c.joint_gain) || !finite(c.max_motor_force) || c.max_motor_force < 0)
        fail("joint_gain must be finite and max_motor_force >= 0");
    if (!(c.blowup_bound > 0) || !(c.max_body_speed > 0) || !finite(c.failure_fitness))
        fail("blowup_bound and max_body_speed must be > 0 and failure_fitness finite");
    if (!finite(o.record_fps) || o.record_fps < 0) fail("record_fps must be >= 0");
}

} // namespace

EvalResult evaluate(const RobotSpec& robot, Controller& controller, const SimConfig& cfg,
                    const EvalOptions& options) {
    check_config(cfg, options);
    const Layout layout = make_layout(robot);

    // QuickStep shuffles constraints with ODE's process-global random state:
    // reset it so every evaluation starts alike, whatever ran before.
    ensure_ode_initialised();
    dRandSetSeed(0);
    World world(layout, cfg);

    const long n_steps = std::lround((cfg.sample_to - cfg.sample_from) / cfg.sample_step);
    const long k_start = std::clamp(
        static_cast<long>(std::ceil((cfg.delayed_start - cfg.sample_from) / cfg.sample_step - 1e-9)), 0L, n_steps);
    const double dt = cfg.sample_step / cfg.step_divider;
    const std::size_t joints = world.joint_count();
    std::vector<double> angles(joints), desired(joints);
    controller.reset(joints);

    EvalResult r;
    if (options.record_fps > 0) {
        r.recording.emplace();
        r.recording->parts = layout.parts();
        r.recording->body_count = layout.body_count;
        r.recording->frame_dt = 1.0 / options.record_fps;
    }
    long next_frame = 0;
    auto fail = [&](std::string why, double t) {
        r.failed = true;
        r.failure = std::move(why);
        r.fitness = cfg.failure_fitness;
        r.simulated_seconds = t - cfg.sample_from;
        for (double& v : r.start) if (!std::isfinite(v)) v = 0;
        r.end = r.start;
        return r;
    };

    for (long k = 0;; ++k) {
        const double t = cfg.sample_from + static_cast<double>(k) * cfg.sample_step;
        if (k == k_start) r.start = world.geom_position(layout.centre_geom);
        if (r.recording && t >= cfg.sample_from + static_cast<double>(next_frame) * r.recording->frame_dt - 1e-9) {
            r.recording->times.push_back(t);
            auto& frame = r.recording->frames.emplace_back();
            for (int b = 0; b < layout.body_count; ++b) frame.push_back(world.body_pose(b));
            ++next_frame;
        }
        if (k == n_steps) break;

        for (std::size_t j = 0; j < joints; ++j) angles[j] = world.joint_angle(j);
        controller.step(t, angles, desired);
        for (double& d : desired) {
            if (!std::isfinite(d)) return fail("the controller gave a non-finite angle at t=" + std::to_string(t), t);
            d = std::clamp(d, -kHingeLimit, kHingeLimit);
        }
        if (options.record_trace)
            r.trace.push_back({t, desired, angles, world.geom_position(layout.centre_geom)});

        for (int s = 0; s < cfg.step_divider; ++s) {
            // The thesis's P-controller, on the current angle every physics step.
            for (std::size_t j = 0; j < joints; ++j)
                world.set_joint_velocity(j, cfg.joint_gain * (world.joint_angle(j) - desired[j]));
            world.step(dt);
            ++r.steps;
            r.ground_contacts += world.last_ground_contacts();
            r.self_contacts += world.last_self_contacts();
            r.max_ground_contacts = std::max(r.max_ground_contacts, world.last_ground_contacts());
            r.max_self_contacts = std::max(r.max_self_contacts, world.last_self_contacts());
            r.max_ground_depth = std::max(r.max_ground_depth, world.last_ground_depth());
            double fastest = 0.0;
            const std::string why = world.check(cfg.blowup_bound, cfg.max_body_speed, fastest);
            if (std::isfinite(fastest)) r.max_body_speed = std::max(r.max_body_speed, fastest);
            if (!why.empty())
                return fail("physics blow-up at t=" + std::to_string(t) + ": " + why, t);
        }
    }
    r.end = world.geom_position(layout.centre_geom);
    r.simulated_seconds = static_cast<double>(n_steps) * cfg.sample_step;
    const std::size_t p = robot.preferred == Axis::X ? 0 : 1;
    r.fitness = std::fabs(r.end[p] - r.start[p]) + (r.end[2] - r.start[2]);
    if (!std::isfinite(r.fitness)) return fail("non-finite fitness", cfg.sample_to);
    return r;
}

} // namespace cic::sim
