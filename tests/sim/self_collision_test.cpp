// Self-collision (Simulator.selfCollision): bodies of one robot that are not
// joined by a hinge collide; geoms are checked for overlap with an independent
// separating-axis test on the recorded poses.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>
#include <utility>

#include "cic/sim/evaluate.hpp"
#include "cic/sim/layout.hpp"

using namespace cic::sim;

namespace {

// How deep two boxes of non-adjacent modules may sink into each other (m) with
// self-collision on. Contacts are soft (softCfm, ERP 0.8), so a few centimetres
// of penetration under a 200 N motor is normal; overlapping bodies, as without
// self-collision, reach tens of centimetres.
constexpr double kOverlapTolerance = 0.05;

using Mat3 = std::array<Vec3, 3>;   // columns: the box's axes in world coordinates

Mat3 rotation(const Pose& p) {
    const double w = p.quat[0], x = p.quat[1], y = p.quat[2], z = p.quat[3];
    return {{{1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)},
             {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)},
             {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)}}};
}

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

struct Box {
    Vec3 centre;
    Mat3 axes;
    Vec3 half;
};

// World box of a recorded part (parts are axis-aligned in their body's frame).
Box world_box(const Part& part, const Pose& body) {
    const Mat3 r = rotation(body);
    Box b;
    for (int k = 0; k < 3; ++k)
        b.centre[k] = body.pos[k] + r[0][k] * part.offset.pos[0] + r[1][k] * part.offset.pos[1] +
                      r[2][k] * part.offset.pos[2];
    b.axes = r;
    for (int k = 0; k < 3; ++k) b.half[k] = part.size[k] / 2;
    return b;
}

// Penetration depth of two boxes by the separating-axis theorem: the smallest
// overlap of their projections over the 15 candidate axes; 0 when separated.
double overlap(const Box& a, const Box& b) {
    std::vector<Vec3> axes;
    for (const auto& u : a.axes) axes.push_back(u);
    for (const auto& v : b.axes) axes.push_back(v);
    for (const auto& u : a.axes)
        for (const auto& v : b.axes) axes.push_back(cross(u, v));
    const Vec3 d{b.centre[0] - a.centre[0], b.centre[1] - a.centre[1], b.centre[2] - a.centre[2]};
    double least = 1e300;
    for (Vec3 l : axes) {
        const double n = std::sqrt(dot(l, l));
        if (n < 1e-9) continue;   // parallel edges: covered by the face axes
        for (double& c : l) c /= n;
        double ra = 0, rb = 0;
        for (int k = 0; k < 3; ++k) {
            ra += a.half[k] * std::fabs(dot(a.axes[k], l));
            rb += b.half[k] * std::fabs(dot(b.axes[k], l));
        }
        const double o = ra + rb - std::fabs(dot(d, l));
        if (o <= 0) return 0.0;
        least = std::min(least, o);
    }
    return least;
}

// The deepest overlap, over all recorded frames, of two geoms on bodies that
// are neither the same body nor joined by a hinge.
double deepest_overlap(const RobotSpec& robot, const Recording& rec) {
    const BodyLayout layout = make_body_layout(robot);
    std::set<std::pair<int, int>> hinged;
    for (const LayoutJoint& j : layout.joints) {
        hinged.insert({j.chassis_body, j.panel_body});
        hinged.insert({j.panel_body, j.chassis_body});
    }
    double deepest = 0;
    for (const auto& frame : rec.frames)
        for (std::size_t i = 0; i < rec.parts.size(); ++i)
            for (std::size_t k = i + 1; k < rec.parts.size(); ++k) {
                const Part& p = rec.parts[i];
                const Part& q = rec.parts[k];
                if (p.body == q.body || hinged.count({p.body, q.body})) continue;
                deepest = std::max(deepest, overlap(world_box(p, frame[p.body]), world_box(q, frame[q.body])));
            }
    return deepest;
}

// A torso of three cubes with two legs of two cubes, one cell apart. Each leg
// swings about z at its hip; at +-90 degrees both feet would sit on the same cell.
RobotSpec pincer() {
    RobotSpec r;
    r.name = "pincer";
    r.modules = {{{0, 0, 0}, Axis::Fixed, Dir::None, "torso.0"},
                 {{0, -1, 0}, Axis::Fixed, Dir::PosY, "torso.-1"},
                 {{0, 1, 0}, Axis::Fixed, Dir::NegY, "torso.+1"},
                 {{1, -1, 0}, Axis::Z, Dir::NegX, "a.hip"},
                 {{2, -1, 0}, Axis::Fixed, Dir::NegX, "a.foot"},
                 {{1, 1, 0}, Axis::Z, Dir::NegX, "b.hip"},
                 {{2, 1, 0}, Axis::Fixed, Dir::NegX, "b.foot"}};
    r.centre = 0;
    r.preferred = Axis::Y;
    return r;
}

// Both hips driven towards the other leg and held there. Weightless, so that
// no ground friction slows the legs: within 4 s they would swing to 85 degrees.
EvalResult close_pincer(bool self_collision) {
    SimConfig cfg;
    cfg.gravity = 0.0;
    cfg.sample_to = 4.0;
    cfg.delayed_start = 0.0;
    cfg.self_collision = self_collision;
    const double hold = std::numbers::pi / 2;   // sin(pi/2) = 1: a constant command
    SineController closing({{hold, 0.0, hold}, {-hold, 0.0, hold}});
    EvalOptions o;
    o.record_fps = 1.0 / cfg.sample_step;   // a frame every control step
    return evaluate(pincer(), closing, cfg, o);
}

} // namespace

TEST(SelfCollision, LegsDrivenIntoEachOtherDoNotPassThrough) {
    const EvalResult on = close_pincer(true);
    ASSERT_FALSE(on.failed) << on.failure;
    ASSERT_TRUE(on.recording);
    EXPECT_GT(on.self_contacts, 0);
    const double with = deepest_overlap(pincer(), *on.recording);
    EXPECT_LE(with, kOverlapTolerance);

    const EvalResult off = close_pincer(false);
    ASSERT_FALSE(off.failed) << off.failure;
    EXPECT_EQ(off.self_contacts, 0);
    const double without = deepest_overlap(pincer(), *off.recording);
    EXPECT_GT(without, 0.3);   // the feet pass into each other
    std::printf("deepest overlap of non-adjacent geoms: %.4f m with self-collision, %.4f m without\n", with, without);
}

TEST(SelfCollision, RestingRobotsHaveNoSelfContacts) {
    // At rest no two bodies of a preset touch: self-collision changes nothing
    // until the robot moves.
    for (int type : {0, 1, 2}) {
        SimConfig cfg;
        cfg.sample_to = 2.0;
        cfg.delayed_start = 0.0;
        ConstantController still(0.0);
        const EvalResult r = evaluate(preset(type, true), still, cfg);
        EXPECT_EQ(r.self_contacts, 0) << "R" << type;
        EXPECT_GT(r.ground_contacts, 0) << "R" << type;
    }
}

TEST(SelfCollision, SixLeggedTripodGaitsStillWalk) {
    // R1 and R2 with 6 legs: the tripod gait moves the centre forward with
    // self-collision on, and the legs do touch on the way.
    for (int type : {1, 2}) {
        SimConfig cfg;   // thesis timing: 15 s, 12.5 ms steps, delayed start 2 s
        SineController gait(tripod_gait(6, 3));
        const EvalResult r = evaluate(preset(type, true), gait, cfg);
        ASSERT_FALSE(r.failed) << r.failure;
        EXPECT_GT(r.fitness, 1.0) << "R" << type;
    }
}
