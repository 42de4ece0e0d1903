// Simulator.collisionSpace: cic's sweep gives the simple space's bits (the
// contacts reach QuickStep in the same order), sweep-and-prune is
// deterministic and finds the same contacts in another order.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "cic/sim/centipede.hpp"
#include "cic/sim/controller.hpp"
#include "cic/sim/evaluate.hpp"

using namespace cic::sim;

namespace {

// A gait with a joint-dependent phase and large swings, so that legs meet the
// ground, and (for R2 and the pincer-like hips) each other.
GaitSpec busy_gait(std::size_t joints, double amplitude) {
    GaitSpec g;
    g.frequency = 0.8;
    for (std::size_t j = 0; j < joints; ++j)
        g.joints.push_back({amplitude, 0.7 * static_cast<double>(j), 0.2 * std::sin(static_cast<double>(j)), 0, 0});
    return g;
}

EvalResult run(const RobotSpec& robot, int space, double amplitude, bool self_collision = true) {
    SimConfig cfg;
    cfg.sample_to = 6.0;
    cfg.collision_space = space;
    cfg.self_collision = self_collision;
    GaitController c(busy_gait(robot.actuated().size(), amplitude));
    return evaluate(robot, c, cfg);
}

std::vector<RobotSpec> robots() {
    std::vector<RobotSpec> out;
    for (int type : {0, 1, 2})
        for (bool middle : {false, true}) out.push_back(preset(type, middle));
    for (int p : {2, 4, 8})
        for (bool irregular : {false, true}) out.push_back(centipede(p, irregular));
    return out;
}

std::string bits(const EvalResult& r) {
    std::string s = std::to_string(std::bit_cast<std::uint64_t>(r.fitness));
    for (double v : r.end) s += " " + std::to_string(std::bit_cast<std::uint64_t>(v));
    return s + " g" + std::to_string(r.max_ground_contacts) + " s" + std::to_string(r.max_self_contacts);
}

} // namespace

TEST(CollisionSpace, SweepGivesTheSimpleSpacesBits) {
    int self_touching = 0;
    for (const RobotSpec& robot : robots())
        for (double amplitude : {0.6, 1.5}) {
            const EvalResult simple = run(robot, kCollisionSimple, amplitude);
            const EvalResult sweep = run(robot, kCollisionSweep, amplitude);
            EXPECT_FALSE(simple.failed) << robot.name;
            EXPECT_EQ(bits(simple), bits(sweep)) << robot.name << " amplitude " << amplitude;
            self_touching += simple.max_self_contacts > 0;
        }
    EXPECT_GT(self_touching, 0);   // the comparison covered robot-robot contacts too
}

// The sweep keeps its order from step to step and puts the pairs in order by
// counting (issue 55): on a long torso that is where it does most of its work.
TEST(CollisionSpace, SweepGivesTheSimpleSpacesBitsOnALongCentipede) {
    for (bool irregular : {false, true}) {
        const RobotSpec robot = centipede(32, irregular);
        const EvalResult simple = run(robot, kCollisionSimple, 1.5);
        EXPECT_FALSE(simple.failed) << robot.name;
        EXPECT_GT(simple.max_ground_contacts, 0) << robot.name;
        EXPECT_EQ(bits(simple), bits(run(robot, kCollisionSweep, 1.5))) << robot.name;
    }
}

TEST(CollisionSpace, SweepWithoutSelfCollisionToo) {
    const RobotSpec r = preset(1, false);
    EXPECT_EQ(bits(run(r, kCollisionSimple, 1.2, false)), bits(run(r, kCollisionSweep, 1.2, false)));
}

TEST(CollisionSpace, SweepAndPruneIsDeterministicAndWalks) {
    for (const RobotSpec& robot : {preset(1, false), centipede(4, true)}) {
        const EvalResult a = run(robot, kCollisionSap, 0.6), b = run(robot, kCollisionSap, 0.6);
        EXPECT_EQ(bits(a), bits(b)) << robot.name;
        EXPECT_FALSE(a.failed) << robot.name;
        EXPECT_GT(a.max_ground_contacts, 0) << robot.name;
    }
}

TEST(CollisionSpace, OutOfRangeIsAConfigProblem) {
    SimConfig c;
    c.collision_space = 3;
    ASSERT_FALSE(config_problems(c).empty());
    EXPECT_EQ(config_problems(c).front().fields.front(), "collision_space");
}
