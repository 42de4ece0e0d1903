// The centipede generator (sim/centipede.hpp): sizes, R1's legs, the irregular twin.
#include <gtest/gtest.h>

#include <map>
#include <stdexcept>

#include "cic/core/limits.hpp"
#include "cic/sim/centipede.hpp"
#include "cic/sim/layout.hpp"

using namespace cic::sim;

namespace {

// Axes of one leg, hip out, by its label ("pair3-x").
std::map<std::string, std::vector<Axis>> legs_of(const RobotSpec& r) {
    std::map<std::string, std::vector<Axis>> out;
    for (const Module& m : r.modules)
        if (m.name.rfind("pair", 0) == 0) out[m.name.substr(0, m.name.find('.'))].push_back(m.axis);
    return out;
}

} // namespace

TEST(Centipede, SizesFollowThePairs) {
    for (int p : {1, 2, 4, 8, 16, 64}) {
        const RobotSpec r = centipede(p, false);
        EXPECT_EQ(r.modules.size(), static_cast<std::size_t>(8 * p - 1)) << p;
        EXPECT_EQ(r.actuated().size(), static_cast<std::size_t>(6 * p)) << p;
        EXPECT_EQ(r.name, "centipede-" + std::to_string(p));
        EXPECT_EQ(r.preferred, Axis::Y);
        EXPECT_EQ(r.modules[static_cast<std::size_t>(r.centre)].name, "torso.0");
        EXPECT_EQ(r.modules[static_cast<std::size_t>(r.centre)].axis, Axis::Fixed);
        EXPECT_NO_THROW(make_body_layout(r));
    }
}

TEST(Centipede, EveryLegIsR1s) {
    const RobotSpec r1 = preset(1, false);
    const auto r1_leg = legs_of(centipede(2, false)).begin()->second;
    std::vector<Axis> preset_leg;
    for (const Module& m : r1.modules)
        if (m.name.rfind("leg+x-y", 0) == 0) preset_leg.push_back(m.axis);
    EXPECT_EQ(r1_leg, preset_leg);
    const auto legs = legs_of(centipede(8, false));
    EXPECT_EQ(legs.size(), 16u);
    for (const auto& [label, axes] : legs) EXPECT_EQ(axes, preset_leg) << label;
}

TEST(Centipede, TorsoIsFixedAndLegsAreTwoCellsApart) {
    const RobotSpec r = centipede(4, false);
    std::vector<int> hip_rows;
    for (const Module& m : r.modules) {
        if (m.cell.x == 0) {
            EXPECT_EQ(m.axis, Axis::Fixed) << m.name;
        }
        if (m.cell.x == 1) hip_rows.push_back(m.cell.y);
    }
    EXPECT_EQ(hip_rows, (std::vector<int>{-3, -1, 1, 3}));
}

TEST(Centipede, IrregularTwinShortensTheFrontLeftLegs) {
    for (int p : {1, 2, 4, 8, 16}) {
        const RobotSpec r = centipede(p, true);
        const int shortened = (p + 1) / 2;
        EXPECT_EQ(r.actuated().size(), static_cast<std::size_t>(6 * p - shortened)) << p;
        EXPECT_EQ(r.name, "centipede-" + std::to_string(p) + "-irregular");
        for (const auto& [label, axes] : legs_of(r)) {
            const int k = std::stoi(label.substr(4));
            const bool short_leg = label.back() == 'x' && label[label.size() - 2] == '-' && k >= p - shortened;
            EXPECT_EQ(axes.size(), short_leg ? 2u : 3u) << p << ' ' << label;
        }
    }
}

TEST(Centipede, IsDeterministic) {
    const RobotSpec a = centipede(5, true), b = centipede(5, true);
    ASSERT_EQ(a.modules.size(), b.modules.size());
    for (std::size_t i = 0; i < a.modules.size(); ++i) {
        EXPECT_EQ(a.modules[i].cell, b.modules[i].cell);
        EXPECT_EQ(a.modules[i].name, b.modules[i].name);
    }
}

TEST(Centipede, BadPairsThrow) {
    EXPECT_THROW(centipede(0, false), std::invalid_argument);
    EXPECT_THROW(centipede(-3, true), std::invalid_argument);
    EXPECT_THROW(centipede(max_centipede_pairs() + 1, false), std::invalid_argument);
    EXPECT_LE(centipede(max_centipede_pairs(), false).modules.size(), cic::limits::kMaxModules);
    EXPECT_GT(8u * static_cast<std::size_t>(max_centipede_pairs() + 1) - 1, cic::limits::kMaxModules);
}
