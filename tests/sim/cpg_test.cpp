// The CPG controller, its neighbourhood and its job text, without and with physics.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "cic/sim/cpg.hpp"
#include "cic/sim/evaluate.hpp"
#include "cic/sim/job_text.hpp"

namespace {

using namespace cic::sim;
constexpr double kPi = std::numbers::pi;

// A centre with an arm of three hinges along +x and one hinge on -x.
RobotSpec arm_robot() {
    RobotSpec r;
    r.name = "arm";
    r.modules = {{{0, 0, 0}, Axis::Fixed, Dir::None, "centre"},
                 {{1, 0, 0}, Axis::Y, Dir::NegX, "a"},
                 {{2, 0, 0}, Axis::Y, Dir::NegX, "b"},
                 {{3, 0, 0}, Axis::Y, Dir::NegX, "c"},
                 {{-1, 0, 0}, Axis::Y, Dir::PosX, "d"}};
    r.centre = 0;
    r.preferred = Axis::X;
    return r;
}

CpgSpec lone(double w) {
    CpgSpec s;
    s.self = {w};
    return s;
}

std::vector<double> run(CpgController& c, int steps, std::vector<double> angles = {}) {
    const std::size_t n = c.spec().self.size();
    if (angles.empty()) angles.assign(n, 0.0);
    std::vector<double> desired(n), out;
    c.reset(n);
    for (int k = 0; k < steps; ++k) {
        c.step(k * c.spec().control_step, angles, desired);
        out.insert(out.end(), desired.begin(), desired.end());
    }
    return out;
}

TEST(CpgNeighbours, CountLinksInTheBodyTree) {
    const RobotSpec r = arm_robot();   // joints a b c d = 0 1 2 3
    EXPECT_EQ(cpg_neighbours(r, 1), (std::vector<CpgEdge>{{0, 1}, {1, 2}}));
    EXPECT_EQ(cpg_neighbours(r, 2), (std::vector<CpgEdge>{{0, 1}, {0, 2}, {0, 3}, {1, 2}}));
    EXPECT_EQ(cpg_neighbours(r, 4).size(), 6u);   // every pair: c-d is 4 links apart
    EXPECT_THROW(cpg_neighbours(r, 0), std::invalid_argument);
}

TEST(CpgController, ALoneOscillatorRunsAtItsWeightOverTwoPi) {
    // x(t) = x0 cos(w t) + y0 sin(w t) exactly; RK4 at 80 Hz is close.
    CpgController c(lone(2 * kPi));   // 1 Hz
    const std::vector<double> cmd = run(c, 81);
    const double x0 = c.spec().initial, range = c.spec().range;
    for (int k = 0; k <= 80; ++k) {
        const double t = k * 0.0125;
        EXPECT_NEAR(cmd[static_cast<std::size_t>(k)] / range, x0 * (std::cos(2 * kPi * t) + std::sin(2 * kPi * t)), 1e-5)
            << "step " << k;
    }
}

TEST(CpgController, OpenLoopConservesTheNormAndClipsToOne) {
    CpgSpec s;
    s.self = {3.0, -2.0, 5.0};
    s.edges = {{0, 1}, {1, 2}, {0, 2}};
    s.coupling = {1.5, -0.7, 0.4};
    s.initial = 0.3;   // small: the clip never acts
    CpgController c(s);
    run(c, 2000);
    double norm = 0;
    for (double v : c.state()) norm += v * v;
    EXPECT_NEAR(norm, 6 * 0.09, 1e-4);   // RK4 dissipates only slightly
    s.initial = 0.7071067811865476;
    s.coupling = {6.0, 6.0, 6.0};
    CpgController big(s);
    for (double v : run(big, 2000)) EXPECT_LE(std::abs(v), s.range + 1e-15);
}

TEST(CpgController, FeedbackPullsTheOscillatorTowardsTheMeasuredAngle) {
    // g (theta / range - x) vanishes while the joint follows its command, and
    // pulls x towards theta when it does not. (RK4 holds theta over the step, so
    // a following joint still leaves an O(h^2) trace.)
    CpgSpec s = lone(4.0);
    CpgController open(s);
    s.feedback = {2.0};
    CpgController following(s), held(s);
    std::vector<double> a(1), b(1), c(1);
    for (auto* ctl : {&open, &following, &held}) ctl->reset(1);
    double gap_following = 0, gap_held = 0;
    for (int k = 0; k < 40; ++k) {
        open.step(0, std::vector<double>{open.state()[0] * s.range}, a);
        following.step(0, std::vector<double>{following.state()[0] * s.range}, b);
        held.step(0, std::vector<double>{0.0}, c);
        gap_following = std::max(gap_following, std::abs(a[0] - b[0]));
        gap_held = std::max(gap_held, std::abs(a[0] - c[0]));
    }
    EXPECT_GT(gap_held, 10 * gap_following) << gap_held << " vs " << gap_following;
    EXPECT_GT(gap_following, 0.0);
}

TEST(CpgController, BadArgumentsThrow) {
    EXPECT_THROW(CpgController(CpgSpec{}), std::invalid_argument);   // no joints
    CpgSpec s = lone(1.0);
    s.edges = {{0, 0}};
    s.coupling = {1.0};
    EXPECT_THROW(CpgController{s}, std::invalid_argument);   // not a < b
    s = lone(1.0);
    s.coupling = {1.0};
    EXPECT_THROW(CpgController{s}, std::invalid_argument);   // sizes disagree
    s = lone(NAN);
    EXPECT_THROW(CpgController{s}, std::invalid_argument);
    s = lone(1.0);
    s.initial = 1.5;
    EXPECT_THROW(CpgController{s}, std::invalid_argument);
    s = lone(1.0);
    s.control_step = 0;
    EXPECT_THROW(CpgController{s}, std::invalid_argument);
    CpgController c(lone(1.0));
    EXPECT_THROW(c.reset(2), std::invalid_argument);
    std::vector<double> two(2);
    EXPECT_THROW(c.step(0, two, two), std::invalid_argument);
}

TEST(CpgController, SameSpecGivesTheSameCommandsAfterReset) {
    CpgSpec s;
    s.self = {3.0, -2.0};
    s.edges = {{0, 1}};
    s.coupling = {1.5};
    CpgController c(s);
    const auto first = run(c, 300);
    EXPECT_EQ(run(c, 300), first);
}

TEST(CpgJob, RoundTripsAndGivesTheSameFitnessBitsAsADirectEvaluation) {
    const RobotSpec robot = preset(0, false);
    SimConfig cfg;
    cfg.sample_to = 2.0;
    cfg.delayed_start = 0.5;
    CpgSpec s;
    const auto joints = robot.actuated().size();
    for (std::size_t i = 0; i < joints; ++i) s.self.push_back(2.0 + 0.1 * static_cast<double>(i));
    s.edges = cpg_neighbours(robot, 2);
    for (std::size_t k = 0; k < s.edges.size(); ++k) s.coupling.push_back(0.3 * static_cast<double>(k % 3) - 0.3);
    s.feedback.assign(joints, 0.5);
    s.control_step = cfg.sample_step;
    const std::string job = make_cpg_job(robot, cfg, s);
    ASSERT_EQ(job.rfind("cpg\n", 0), 0u);
    std::istringstream in(job.substr(4));
    (void)read_robot_text(in);
    (void)read_config_text(in);
    const CpgSpec back = read_cpg_spec(in);
    EXPECT_EQ(back.self, s.self);
    EXPECT_EQ(back.edges, s.edges);
    EXPECT_EQ(back.coupling, s.coupling);
    EXPECT_EQ(back.feedback, s.feedback);
    CpgController direct(s);
    const EvalReply reply = parse_eval_reply(run_cpg_job(job.substr(4)));
    EXPECT_EQ(reply.fitness, evaluate(robot, direct, cfg).fitness);
    EXPECT_FALSE(reply.failed);
    s.self[0] = INFINITY;
    EXPECT_THROW(make_cpg_job(robot, cfg, s), std::invalid_argument);
    EXPECT_THROW(run_cpg_job(job.substr(4, job.size() / 2)), std::invalid_argument);
}

} // namespace
