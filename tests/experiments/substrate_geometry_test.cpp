// Robot description -> substrate geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cic/core/error.hpp"
#include "cic/experiments/hypergp/substrate_geometry.hpp"
#include "cic/sim/centipede.hpp"

using cic::nn::Point;
using cic::sim::Axis;
using cic::sim::Dir;

namespace {

// Centre at (0,0), an arm of two hinged modules along +x, a fixed module at (0,1).
cic::sim::RobotSpec small_robot() {
    cic::sim::RobotSpec r;
    r.name = "small";
    r.modules = {{{0, 0, 0}, Axis::Fixed, Dir::None, "centre"},
                 {{1, 0, 0}, Axis::Y, Dir::NegX, "arm.0"},
                 {{0, 1, 0}, Axis::Fixed, Dir::NegY, "head"},
                 {{2, 0, 0}, Axis::Z, Dir::NegX, "arm.1"}};
    return r;
}

} // namespace

TEST(SubstrateGeometry, ModulesNormalisedOverTheBoundingBox) {
    const auto g = cic::hypergp::substrate_geometry(small_robot());
    // x in [0, 2] -> -1, 0, 1; y in [0, 1] -> -1, 1. Joints in actuated() order.
    EXPECT_EQ(g.joints, (std::vector<Point>{{0, -1}, {1, -1}}));
    EXPECT_EQ(g.hidden, (std::vector<Point>{{-1, -1}, {0, -1}, {-1, 1}, {1, -1}}));
}

TEST(SubstrateGeometry, DegenerateAxisMapsToZero) {
    auto r = small_robot();
    r.modules.erase(r.modules.begin() + 2);   // drop the head: a straight line along x
    const auto g = cic::hypergp::substrate_geometry(r);
    EXPECT_EQ(g.joints, (std::vector<Point>{{0, 0}, {1, 0}}));
    EXPECT_EQ(g.hidden, (std::vector<Point>{{-1, 0}, {0, 0}, {1, 0}}));
}

TEST(SubstrateGeometry, ThesisR1HasOneNeuronPerJointAndPerModule) {
    for (bool six : {false, true}) {
        const auto robot = cic::sim::preset(1, six);
        const auto g = cic::hypergp::substrate_geometry(robot);
        EXPECT_EQ(g.joints.size(), robot.actuated().size());
        EXPECT_EQ(g.joints.size(), six ? 18u : 12u);
        EXPECT_EQ(g.hidden.size(), robot.modules.size());
        // The robot is mirror-symmetric in x, and so is its substrate.
        for (const auto& p : g.hidden) {
            EXPECT_GE(p.x, -1.0);
            EXPECT_LE(p.x, 1.0);
            EXPECT_GE(p.y, -1.0);
            EXPECT_LE(p.y, 1.0);
            EXPECT_NE(std::find(g.hidden.begin(), g.hidden.end(), Point{-p.x, p.y}), g.hidden.end());
        }
    }
}

TEST(SubstrateGeometry, BadRobotsThrow) {
    auto r = small_robot();
    for (auto& m : r.modules) m.axis = Axis::Fixed;
    EXPECT_THROW(cic::hypergp::substrate_geometry(r), std::invalid_argument);
    r = small_robot();
    r.modules[3].cell = r.modules[1].cell;   // overlapping cells
    EXPECT_THROW(cic::hypergp::substrate_geometry(r), cic::InputError);
}

// Neural.substrateLayout absolute: cells from the centre module over
// substrateUnit, whatever the body's size; the default is the normalised layout.
TEST(SubstrateGeometry, AbsoluteLayoutCountsCellsFromTheCentreModule) {
    cic::nn::NeuralConfig cfg;
    EXPECT_EQ(cfg.substrate_layout, cic::nn::SubstrateLayout::Normalised);
    EXPECT_EQ(cic::hypergp::substrate_geometry(small_robot(), cfg).joints,
              cic::hypergp::substrate_geometry(small_robot()).joints);
    cfg.substrate_layout = cic::nn::SubstrateLayout::Absolute;
    cfg.substrate_unit = 2.0;
    auto r = small_robot();
    const auto g = cic::hypergp::substrate_geometry(r, cfg);
    EXPECT_EQ(g.joints, (std::vector<Point>{{0.5, 0}, {1, 0}}));
    EXPECT_EQ(g.hidden, (std::vector<Point>{{0, 0}, {0.5, 0}, {0, 0.5}, {1, 0}}));
    for (auto& m : r.modules) m.cell.x += 5;   // the whole body moved: no neuron moves
    EXPECT_EQ(cic::hypergp::substrate_geometry(r, cfg).joints, g.joints);
    cfg.substrate_unit = 0.0;
    EXPECT_THROW(cic::hypergp::substrate_geometry(r, cfg), std::invalid_argument);
}

// A bigger centipede keeps its legs' spacing in the absolute layout (and is
// queried past [-1, 1]), where the normalised layout squeezes them; mirrored
// legs keep exactly opposite coordinates in both.
TEST(SubstrateGeometry, AbsoluteLayoutKeepsTheSpacingOfABiggerBody) {
    cic::nn::NeuralConfig absolute;
    absolute.substrate_layout = cic::nn::SubstrateLayout::Absolute;
    absolute.substrate_unit = 3.0;
    auto spacing = [](const cic::nn::Geometry& g) {   // the smallest y step between two joints
        double step = 1e9;
        for (const auto& a : g.joints)
            for (const auto& b : g.joints)
                if (a.y != b.y) step = std::min(step, std::abs(a.y - b.y));
        return step;
    };
    const auto small = cic::sim::centipede(2, false), big = cic::sim::centipede(8, false);
    EXPECT_EQ(spacing(cic::hypergp::substrate_geometry(small, absolute)),
              spacing(cic::hypergp::substrate_geometry(big, absolute)));
    EXPECT_GT(spacing(cic::hypergp::substrate_geometry(small)), spacing(cic::hypergp::substrate_geometry(big)));
    const auto g = cic::hypergp::substrate_geometry(big, absolute);
    double reach = 0;
    for (const auto& p : g.hidden) {
        reach = std::max(reach, std::abs(p.y));
        EXPECT_NE(std::find(g.hidden.begin(), g.hidden.end(), Point{-p.x, p.y}), g.hidden.end());
    }
    EXPECT_GT(reach, 1.0);
}
