// Evaluations: standing still, walking, determinism, blow-ups, recording.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "cic/core/rng.hpp"
#include "cic/sim/evaluate.hpp"
#include "cic/sim/layout.hpp"

using namespace cic::sim;

namespace {

SimConfig short_config(double seconds = 3.0) {
    SimConfig c;
    c.sample_to = seconds;
    c.delayed_start = std::min(1.0, seconds / 2);
    return c;
}

std::uint64_t bits(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

// The tripod gait that walks R1 with 6 legs forward (sim::tripod_gait).
std::vector<SineJoint> r1_gait() { return tripod_gait(6, 3); }

std::vector<SineJoint> random_sine(cic::Rng& rng, std::size_t joints) {
    std::vector<SineJoint> g;
    for (std::size_t j = 0; j < joints; ++j)
        g.push_back({rng.uniform(0.0, 1.5), rng.uniform(0.1, 1.5), rng.uniform(0.0, 2 * std::numbers::pi)});
    return g;
}

} // namespace

TEST(Evaluate, ConstantControllerStandsStill) {
    for (int type : {0, 1, 2}) {
        ConstantController still(0.0);
        const EvalResult r = evaluate(preset(type, type == 1), still, short_config());
        EXPECT_FALSE(r.failed) << r.failure;
        EXPECT_NEAR(r.fitness, 0.0, 1e-3) << "R" << type;
        EXPECT_NEAR(r.end[2], 0.5, 0.02);   // the centre cube rests on the ground
        EXPECT_EQ(r.steps, 240);
        EXPECT_DOUBLE_EQ(r.simulated_seconds, 3.0);
    }
}

TEST(Evaluate, TunedSineGaitMovesR1Forward) {
    const RobotSpec robot = preset(1, true);
    SineController gait(r1_gait());
    SimConfig cfg = short_config(6.0);
    const EvalResult r = evaluate(robot, gait, cfg);
    EXPECT_FALSE(r.failed) << r.failure;
    const double forward = r.end[1] - r.start[1];
    EXPECT_GT(forward, 1.5);                              // ~2.8 along +y, its preferred axis, in 5 s
    EXPECT_GT(forward, 10 * std::fabs(r.end[0] - r.start[0]));
    EXPECT_GT(r.fitness, 1.5);
}

// Each foot's ground contacts, counted only when asked, change nothing the
// plain evaluation computes: the fitness has the same bits.
TEST(Evaluate, GroundContactsPerModuleAreCountedOnlyWhenAskedAndChangeNothing) {
    const RobotSpec robot = preset(1, true);
    const SimConfig cfg = short_config(4.0);
    SineController a(r1_gait()), b(r1_gait());
    const EvalResult plain = evaluate(robot, a, cfg);
    EXPECT_TRUE(plain.module_ground_steps.empty());
    EXPECT_EQ(plain.ground_steps, 0);
    EvalOptions opt;
    opt.record_ground = true;
    const EvalResult counted = evaluate(robot, b, cfg, opt);
    EXPECT_EQ(bits(counted.fitness), bits(plain.fitness));
    ASSERT_EQ(counted.module_ground_steps.size(), robot.modules.size());
    // Physics steps from the delayed start (1 s) to the end (4 s).
    EXPECT_EQ(counted.ground_steps, std::lround(3.0 / cfg.sample_step) * cfg.step_divider);
    const std::vector<int> feet = branch_ends(robot);
    ASSERT_EQ(feet.size(), 6u);   // the six legs' ends
    long on_ground = 0;
    for (int f : feet) {
        EXPECT_EQ(robot.modules[static_cast<std::size_t>(f)].name.substr(robot.modules[static_cast<std::size_t>(f)].name.size() - 2), ".2");
        EXPECT_LE(counted.module_ground_steps[static_cast<std::size_t>(f)], counted.ground_steps);
        on_ground += counted.module_ground_steps[static_cast<std::size_t>(f)];
    }
    EXPECT_GT(on_ground, 0) << "a walking robot's feet touch the ground";
    // The duty factors: one per foot, each its share of the steps.
    EXPECT_TRUE(duty_factors(robot, plain).empty());
    const std::vector<double> duty = duty_factors(robot, counted);
    ASSERT_EQ(duty.size(), feet.size());
    for (std::size_t i = 0; i < feet.size(); ++i)
        EXPECT_EQ(duty[i], static_cast<double>(counted.module_ground_steps[static_cast<std::size_t>(feet[i])]) /
                               static_cast<double>(counted.ground_steps));
    EXPECT_THROW(duty_factors(preset(1, false), counted), std::invalid_argument);
    EXPECT_EQ(counted.module_ground_steps[static_cast<std::size_t>(robot.centre)] > counted.ground_steps / 2, false)
        << "the torso is carried, not dragged";
}

TEST(Evaluate, MotorFollowsTheCommandWithTheThesisGain) {
    // A held command of 0.5 rad: with gain -1 the joints approach it.
    ConstantController hold(0.5);
    EvalOptions o;
    o.record_trace = true;
    const EvalResult r = evaluate(preset(2, false), hold, short_config(6.0), o);
    ASSERT_EQ(r.trace.size(), 480u);
    for (double a : r.trace.back().actual) EXPECT_NEAR(a, 0.5, 0.1);
    for (double d : r.trace.back().desired) EXPECT_EQ(d, 0.5);
    // Commands past the hinge range are clamped.
    ConstantController far(3.0);
    SimConfig brief = short_config(0.5);
    brief.delayed_start = 0.0;
    const EvalResult c = evaluate(preset(0, false), far, brief, o);
    for (double d : c.trace.front().desired) EXPECT_DOUBLE_EQ(d, std::numbers::pi / 2);
}

TEST(Evaluate, SameBitsWhateverTheOrder) {
    cic::Rng rng(7);
    const RobotSpec robot = preset(1, false);
    SineController a(random_sine(rng, 12)), b(random_sine(rng, 12));
    const SimConfig cfg = short_config();
    const double a1 = evaluate(robot, a, cfg).fitness;
    const double b1 = evaluate(robot, b, cfg).fitness;
    const double b2 = evaluate(robot, b, cfg).fitness;
    const double a2 = evaluate(robot, a, cfg).fitness;
    EXPECT_EQ(bits(a1), bits(a2));
    EXPECT_EQ(bits(b1), bits(b2));
    EXPECT_NE(bits(a1), bits(b1));
}

TEST(Evaluate, BlowUpIsAFailedResultNotACrash) {
    SimConfig cfg = short_config();
    cfg.joint_gain = -1e6;          // absurd motor (the range's end): the world explodes
    cfg.max_motor_force = 1e12;
    cfg.blowup_bound = 50.0;
    SineController wild({{1.5, 3.0, 0.0}});
    const EvalResult r = evaluate(preset(1, false), wild, cfg);
    EXPECT_TRUE(r.failed);
    EXPECT_EQ(r.fitness, cfg.failure_fitness);
    EXPECT_NE(r.failure.find("blow-up"), std::string::npos) << r.failure;
    for (double v : r.start) EXPECT_TRUE(std::isfinite(v));
    for (double v : r.end) EXPECT_TRUE(std::isfinite(v));
}

TEST(Evaluate, CoarseStepsAreRefusedUnlessAllowed) {
    // Thesis 7.2.3 with extraTimeStepDivider 1: a physics step of 0.5 s.
    SimConfig cfg;
    cfg.sample_step = 0.5;
    SineController gait(tripod_gait(6, 3));
    EXPECT_THROW(evaluate(preset(1, true), gait, cfg), std::invalid_argument);
    cfg.allow_coarse_step = true;   // on request it runs (and parts sink into the ground)
    EXPECT_FALSE(evaluate(preset(1, true), gait, cfg).failed);
    // The thesis's own coarse set-up, 0.5 s / 20 = 25 ms, is within the bound.
    cfg.allow_coarse_step = false;
    cfg.step_divider = 20;
    EXPECT_FALSE(evaluate(preset(1, true), gait, cfg).failed);
}

TEST(Evaluate, ABodyFasterThanTheBoundIsABlowUp) {
    // The tripod gait moves parts at up to ~8 m/s; a bound of 2 m/s catches it.
    SimConfig cfg;
    SineController gait(tripod_gait(6, 3));
    ASSERT_FALSE(evaluate(preset(1, true), gait, cfg).failed);
    cfg.max_body_speed = 2.0;
    const EvalResult r = evaluate(preset(1, true), gait, cfg);
    EXPECT_TRUE(r.failed);
    EXPECT_EQ(r.fitness, cfg.failure_fitness);
    EXPECT_NE(r.failure.find("maxBodySpeed"), std::string::npos) << r.failure;
}

TEST(Evaluate, NonFiniteCommandFailsTheEvaluation) {
    ConstantController nan_angle(std::nan(""));
    const EvalResult r = evaluate(preset(0, false), nan_angle, short_config(1.0));
    EXPECT_TRUE(r.failed);
    EXPECT_TRUE(std::isfinite(r.fitness));
}

TEST(Evaluate, BadConfigThrows) {
    ConstantController c;
    const RobotSpec robot = preset(0, false);
    auto with = [](auto change) { SimConfig cfg = short_config(); change(cfg); return cfg; };
    EXPECT_THROW(evaluate(robot, c, with([](SimConfig& s) { s.sample_step = 0; })), std::invalid_argument);
    EXPECT_THROW(evaluate(robot, c, with([](SimConfig& s) { s.sample_to = -1; })), std::invalid_argument);
    EXPECT_THROW(evaluate(robot, c, with([](SimConfig& s) { s.step_divider = 0; })), std::invalid_argument);
    EXPECT_THROW(evaluate(robot, c, with([](SimConfig& s) { s.delayed_start = 99; })), std::invalid_argument);
    EXPECT_THROW(evaluate(robot, c, with([](SimConfig& s) { s.max_contacts = 0; })), std::invalid_argument);
    EXPECT_THROW(evaluate(robot, c, with([](SimConfig& s) { s.friction = -1; })), std::invalid_argument);
    EXPECT_THROW(evaluate(robot, c, with([](SimConfig& s) { s.max_body_speed = 0; })), std::invalid_argument);
    EXPECT_THROW(SineController({}), std::invalid_argument);
}

TEST(Evaluate, RecordsFramesOfEveryBody) {
    const RobotSpec robot = preset(0, false);
    SineController gait({{0.6, 0.5, 0.0}});
    EvalOptions o;
    o.record_fps = 10;
    SimConfig cfg = short_config(2.0);
    cfg.step_divider = 2;
    const EvalResult r = evaluate(robot, gait, cfg, o);
    ASSERT_TRUE(r.recording);
    const Recording& rec = *r.recording;
    EXPECT_EQ(rec.body_count, make_body_layout(robot).body_count);
    EXPECT_EQ(rec.parts.size(), 2 * robot.modules.size() - 1);
    EXPECT_EQ(rec.frames.size(), 21u);   // t = 0, 0.1, ..., 2.0
    EXPECT_EQ(rec.times.size(), rec.frames.size());
    EXPECT_NEAR(rec.times[10], 1.0, 1e-9);
    for (const auto& f : rec.frames) EXPECT_EQ(f.size(), static_cast<std::size_t>(rec.body_count));
    EXPECT_EQ(r.steps, 2 * 160);
    EXPECT_TRUE(r.trace.empty());
}
