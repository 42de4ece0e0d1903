// `cic simulate`: one evaluation of a robot under a baseline controller, with
// its fitness and speed. How a user checks a new robot file before evolving it.
#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cic/cli/commands.hpp"
#include "cic/report/preset_replay.hpp"
#include "cic/core/error.hpp"
#include "cic/io/robot_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/sim/evaluate.hpp"
#include "cic/sim/layout.hpp"

namespace cic::cli {

namespace {

struct SimulateOptions {
    std::string robot;                  // R0 | R1 | R2 | FILE; empty = from the settings
    bool middle_legs = false;
    std::string controller = "sine";
    std::string settings;
    std::vector<std::string> overrides; // --set Section.key=value
    double seconds = 0.0;               // 0 = the settings' sample_to
};

int simulate(const SimulateOptions& o) {
    const io::Settings settings = io::load_settings(o.settings, o.overrides);
    sim::SimConfig cfg = settings.sim;
    if (o.seconds < 0) throw InputError(fmt::format("--seconds {} must be > 0", o.seconds));
    if (o.seconds > 0) {
        cfg.sample_to = cfg.sample_from + o.seconds;
        if (cfg.delayed_start > cfg.sample_to) cfg.delayed_start = cfg.sample_from;
    }
    sim::RobotSpec robot;
    if (!o.robot.empty())
        robot = io::load_robot(o.robot, o.middle_legs);
    else if (!settings.robot.robot_file.empty())
        robot = io::read_robot_file(settings.robot.robot_file);
    else
        robot = sim::preset(settings.robot.robot_type, o.middle_legs || settings.neural.middle_legs);
    const sim::BodyLayout layout = sim::make_body_layout(robot);
    auto controller = report::parse_controller_spec(o.controller);

    const auto t0 = std::chrono::steady_clock::now();
    const sim::EvalResult r = sim::evaluate(robot, *controller, cfg);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    fmt::print("robot           {} ({} modules, {} bodies, {} joints, preferred axis {})\n",
               robot.name.empty() ? o.robot : robot.name, robot.modules.size(), layout.body_count,
               layout.joints.size(), sim::to_string(robot.preferred));
    fmt::print("controller      {}\n", o.controller);
    fmt::print("fitness         {:.6f}{}\n", r.fitness, r.failed ? "  (FAILED: " + r.failure + ")" : "");
    fmt::print("centre moved    from ({:.3f}, {:.3f}, {:.3f}) to ({:.3f}, {:.3f}, {:.3f})\n", r.start[0],
               r.start[1], r.start[2], r.end[0], r.end[1], r.end[2]);
    fmt::print("simulated time  {:.3f} s ({} physics steps of {} s)\n", r.simulated_seconds, r.steps,
               cfg.sample_step / cfg.step_divider);
    const double steps = static_cast<double>(std::max(1L, r.steps));
    fmt::print("ground contacts {:.2f} per step (at most {})\n", static_cast<double>(r.ground_contacts) / steps,
               r.max_ground_contacts);
    fmt::print("self contacts   {}\n", cfg.self_collision
                                         ? fmt::format("{:.2f} per step (at most {})",
                                                       static_cast<double>(r.self_contacts) / steps,
                                                       r.max_self_contacts)
                                         : std::string("off (Simulator.selfCollision = 0)"));
    fmt::print("deepest ground contact {:.4f} m, fastest body {:.3f} m/s\n", r.max_ground_depth, r.max_body_speed);
    fmt::print("wall time       {:.4f} s\n", wall);
    fmt::print("real-time factor {:.1f}x\n", wall > 0 ? r.simulated_seconds / wall : 0.0);
    return r.failed ? 1 : 0;
}

} // namespace

void add_simulate_command(Command& app, CommandContext& ctx) {
    auto o = std::make_shared<SimulateOptions>();
    Command cmd = app.subcommand("simulate", "Run one evaluation of a robot under a baseline controller");
    cmd.option("--robot", o->robot, "R0, R1, R2 or a robot file (default: the settings' robot)");
    cmd.flag("--middle-legs", o->middle_legs, "With R0/R1/R2: add the middle pair of legs");
    cmd.option("--controller", o->controller,
                    "sine (= sine:0.8,0.5) | sine:AMPLITUDE,FREQUENCY[,PHASE_STEP] | constant (= constant:0) | constant:ANGLE")
        .show_default();
    cmd.option("--settings", o->settings, "Settings file (its Simulator section is used)");
    cmd.option("--set", o->overrides, "Override Section.key=value (repeatable), e.g. Simulator.sample_step=0.025");
    cmd.option("--seconds", o->seconds, "Simulated time (default: the settings' sample_to)");
    cmd.on_run([o, &ctx] { ctx.exit_code = simulate(*o); });
}

} // namespace cic::cli
