// The baseline controllers and the tripod gait, without physics.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "cic/sim/controller.hpp"

namespace {

using namespace cic::sim;
constexpr double kPi = std::numbers::pi;

TEST(Controller, SineFollowsItsFormulaAndReusesTheLastJoint) {
    SineController c({{0.5, 1.0, 0.0}, {0.25, 0.5, kPi / 2}});
    c.reset(3);
    std::vector<double> angles(3, 0.0), desired(3);
    c.step(0.125, angles, desired);
    EXPECT_DOUBLE_EQ(desired[0], 0.5 * std::sin(2 * kPi * 1.0 * 0.125));
    EXPECT_DOUBLE_EQ(desired[1], 0.25 * std::sin(2 * kPi * 0.5 * 0.125 + kPi / 2));
    EXPECT_DOUBLE_EQ(desired[2], desired[1]);
}

TEST(Controller, ConstantHoldsItsAngle) {
    ConstantController c(0.3);
    c.reset(2);
    std::vector<double> angles(2, 1.0), desired(2);
    c.step(4.0, angles, desired);
    EXPECT_EQ(desired, (std::vector<double>{0.3, 0.3}));
}

TEST(TripodGait, RejectsBadArguments) {
    EXPECT_THROW(tripod_gait(0, 3), std::invalid_argument);
    EXPECT_THROW(tripod_gait(4, 0), std::invalid_argument);
}

TEST(TripodGait, NeighbouringLegsAreHalfAPeriodApartAndLaterJointsLagAQuarter) {
    const auto g = tripod_gait(6, 3, 0.8, 0.25);
    ASSERT_EQ(g.size(), 18u);
    for (const auto& j : g) {
        EXPECT_DOUBLE_EQ(j.amplitude, 0.8);
        EXPECT_DOUBLE_EQ(j.frequency, 0.25);
    }
    // Legs in pairs along the torso, +x then -x: 0 and 3 and 4 lift together, 1, 2 and 5 half a period later.
    const double hip[6] = {0, kPi, kPi, 0, 0, kPi};
    for (int leg = 0; leg < 6; ++leg) {
        EXPECT_DOUBLE_EQ(g[static_cast<std::size_t>(leg * 3)].phase, hip[leg]) << "leg " << leg;
        for (int k = 1; k < 3; ++k)
            EXPECT_DOUBLE_EQ(g[static_cast<std::size_t>(leg * 3 + k)].phase, hip[leg] + kPi / 2);
    }
}

} // namespace
