// One deterministic evaluation: world, control loop, fitness (thesis eq. 7.1).
#include "cic/sim/evaluate.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "world.hpp"

namespace cic::sim {

namespace {

void check_config(const SimConfig& c, const EvalOptions& o) {
    if (auto problems = config_problems(c); !problems.empty())
        throw std::invalid_argument("SimConfig: " + problems.front().why);
    if (!std::isfinite(o.record_fps) || o.record_fps < 0)
        throw std::invalid_argument("SimConfig: record_fps must be >= 0");
}

} // namespace

EvalResult evaluate(const RobotSpec& robot, Controller& controller, const SimConfig& cfg,
                    const EvalOptions& options) {
    check_config(cfg, options);
    const BodyLayout layout = make_body_layout(robot);

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
    if (options.record_ground) {
        world.track_ground_geoms(true);
        r.module_ground_steps.assign(robot.modules.size(), 0);
    }
    // Each foot's contacts per trace row (a fitness that needs the whole walk pays only when it asks).
    const std::vector<int> feet = options.record_ground && options.record_trace ? branch_ends(robot) : std::vector<int>{};
    std::vector<char> module_touched(robot.modules.size(), 0);
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
        if (options.record_trace) {
            r.trace.push_back({t, desired, angles, world.geom_position(layout.centre_geom), {}});
            r.trace.back().feet_on_ground.assign(feet.size(), 0);
        }

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
            if (options.record_ground) {
                const auto& touched = world.last_ground_geoms();
                std::fill(module_touched.begin(), module_touched.end(), 0);
                for (std::size_t g = 0; g < touched.size(); ++g)
                    if (touched[g]) module_touched[static_cast<std::size_t>(layout.geoms[g].module)] = 1;
                if (k >= k_start) {
                    ++r.ground_steps;
                    for (std::size_t m = 0; m < module_touched.size(); ++m) r.module_ground_steps[m] += module_touched[m];
                }
                for (std::size_t f = 0; f < feet.size(); ++f)
                    if (module_touched[static_cast<std::size_t>(feet[f])]) r.trace.back().feet_on_ground[f] = 1;
            }
            double fastest = 0.0;
            const std::string why = world.check(cfg.blowup_bound, cfg.max_body_speed, fastest);
            if (std::isfinite(fastest)) r.max_body_speed = std::max(r.max_body_speed, fastest);
            if (!why.empty())
                return fail("physics blow-up at t=" + std::to_string(t) + ": " + why, t);
        }
    }
    r.end = world.geom_position(layout.centre_geom);
    r.simulated_seconds = static_cast<double>(n_steps) * cfg.sample_step;
    const auto [distance, elevation] = walk_terms(robot, r);
    r.fitness = distance + elevation;
    if (!std::isfinite(r.fitness)) return fail("non-finite fitness", cfg.sample_to);
    return r;
}

std::pair<double, double> walk_terms(const RobotSpec& robot, const EvalResult& r) {
    const std::size_t p = robot.preferred == Axis::X ? 0 : 1;
    return {std::fabs(r.end[p] - r.start[p]), r.end[2] - r.start[2]};
}

std::vector<int> branch_ends(const RobotSpec& robot) {
    const std::size_t n = robot.modules.size();
    std::vector<char> carries(n, 0);   // some module attaches to it
    for (std::size_t m = 0; m < n; ++m) {
        const Module& mod = robot.modules[m];
        if (mod.attach == Dir::None) continue;
        const Cell next = neighbour(mod.cell, mod.attach);
        for (std::size_t o = 0; o < n; ++o)
            if (robot.modules[o].cell == next) carries[o] = 1;
    }
    std::vector<int> ends;
    for (std::size_t m = 0; m < n; ++m)
        if (!carries[m] && static_cast<int>(m) != robot.centre) ends.push_back(static_cast<int>(m));
    return ends;
}

namespace {
std::string module_name(const RobotSpec& robot, int m) {
    const std::string& name = robot.modules[static_cast<std::size_t>(m)].name;
    return name.empty() ? "m" + std::to_string(m) : name;
}
} // namespace

std::vector<std::string> joint_names(const RobotSpec& robot) {
    std::vector<std::string> names;
    for (int m : robot.actuated()) names.push_back(module_name(robot, m));
    return names;
}

std::vector<std::string> foot_names(const RobotSpec& robot) {
    std::vector<std::string> names;
    for (int m : branch_ends(robot)) names.push_back(module_name(robot, m));
    return names;
}

std::vector<double> duty_factors(const RobotSpec& robot, const EvalResult& result) {
    std::vector<double> out;
    if (result.module_ground_steps.empty()) return out;
    if (result.module_ground_steps.size() != robot.modules.size())
        throw std::invalid_argument("duty_factors: the result counts " + std::to_string(result.module_ground_steps.size()) +
                                    " modules, the robot has " + std::to_string(robot.modules.size()));
    for (int m : branch_ends(robot))
        out.push_back(result.ground_steps > 0 ? static_cast<double>(result.module_ground_steps[static_cast<std::size_t>(m)]) /
                                                    static_cast<double>(result.ground_steps)
                                              : 0.0);
    return out;
}

std::string to_string(Descriptor d) {
    switch (d) {
    case Descriptor::None: return "none";
    case Descriptor::DutyFactor: return "duty-factor";
    case Descriptor::Omni: return "omni";
    }
    return "?";
}

Descriptor descriptor_from(const std::string& name) {
    for (Descriptor d : {Descriptor::None, Descriptor::DutyFactor, Descriptor::Omni})
        if (to_string(d) == name) return d;
    throw std::invalid_argument("unknown behaviour descriptor '" + name + "' (allowed: none, duty-factor, omni)");
}

std::vector<double> descriptor_of(Descriptor d, const RobotSpec& robot, const EvalResult& result) {
    switch (d) {
    case Descriptor::None: return {};
    case Descriptor::DutyFactor:
        if (result.module_ground_steps.empty())
            throw std::invalid_argument("descriptor_of: duty factors need the ground recorded");
        return duty_factors(robot, result);
    case Descriptor::Omni: return {result.end[0] - result.start[0], result.end[1] - result.start[1]};
    }
    return {};
}

} // namespace cic::sim
