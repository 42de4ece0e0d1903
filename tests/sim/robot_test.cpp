// Presets, validation and layout (bodies and hinges) of RobotSpec.
#include <gtest/gtest.h>

#include "cic/core/error.hpp"
#include "cic/sim/layout.hpp"
#include "cic/sim/robot.hpp"

using namespace cic::sim;

namespace {

struct Extent {
    int x = 0, y = 0;
};
Extent footprint(const RobotSpec& r) {
    int x0 = 1 << 20, x1 = -(1 << 20), y0 = 1 << 20, y1 = -(1 << 20);
    for (const Module& m : r.modules) {
        x0 = std::min(x0, m.cell.x), x1 = std::max(x1, m.cell.x);
        y0 = std::min(y0, m.cell.y), y1 = std::max(y1, m.cell.y);
    }
    return {x1 - x0 + 1, y1 - y0 + 1};
}

std::string problem_of(const RobotSpec& r) {
    try {
        r.validate();
    } catch (const cic::InputError& e) {
        return e.what();
    }
    return "";
}

RobotSpec two_modules() {
    RobotSpec r;
    r.name = "pair";
    r.modules = {{{0, 0, 0}, Axis::Fixed, Dir::None, "a"}, {{1, 0, 0}, Axis::Y, Dir::NegX, "b"}};
    return r;
}

} // namespace

TEST(Preset, MatchesTheThesisTable) {
    struct Row { int type; int torso; int leg; Axis preferred; int size_x, size_y; std::vector<Axis> axes; };
    const Row rows[] = {{0, 5, 2, Axis::X, 5, 5, {Axis::Y, Axis::Y}},
                        {1, 7, 3, Axis::Y, 7, 7, {Axis::Y, Axis::Z, Axis::Y}},
                        {2, 5, 3, Axis::Y, 7, 5, {Axis::Z, Axis::Y, Axis::Y}}};
    for (const Row& row : rows) {
        for (bool middle : {false, true}) {
            const RobotSpec r = preset(row.type, middle);
            const int legs = middle ? 6 : 4;
            EXPECT_NO_THROW(r.validate());
            EXPECT_EQ(r.modules.size(), static_cast<std::size_t>(row.torso + legs * row.leg));
            EXPECT_EQ(r.preferred, row.preferred);
            const Extent e = footprint(r);
            EXPECT_EQ(e.x, row.size_x) << "R" << row.type;
            EXPECT_EQ(e.y, row.size_y) << "R" << row.type;
            // The centre is the torso's middle cube.
            EXPECT_EQ(r.modules[r.centre].cell, (Cell{0, 0, 0}));
            // Joint axes from the hip out, leg modules attached towards the torso.
            int leg_modules = 0;
            for (const Module& m : r.modules) {
                if (m.cell.x == 0) {
                    EXPECT_EQ(m.axis, Axis::Fixed);
                    continue;
                }
                ++leg_modules;
                const int k = std::abs(m.cell.x) - 1;
                EXPECT_EQ(m.axis, row.axes[k]);
                EXPECT_EQ(m.attach, m.cell.x > 0 ? Dir::NegX : Dir::PosX);
                EXPECT_EQ(std::abs(m.cell.y) == row.torso / 2 || (middle && m.cell.y == 0), true);
            }
            EXPECT_EQ(leg_modules, legs * row.leg);
        }
    }
    EXPECT_THROW(preset(3, false), std::invalid_argument);
    EXPECT_THROW(preset(-1, true), std::invalid_argument);
}

TEST(BodyLayout, PresetBodyAndJointCounts) {
    // The torso and every hip panel form one body; each leg module's chassis
    // carries the next module's panel, so each leg module adds one body and one hinge.
    // bodies = 1 + legs * leg_length, joints = legs * leg_length.
    struct Row { int type; bool middle; int bodies; int joints; };
    const Row rows[] = {{0, false, 1 + 4 * 2, 4 * 2}, {0, true, 1 + 6 * 2, 6 * 2},
                        {1, false, 1 + 4 * 3, 4 * 3}, {1, true, 1 + 6 * 3, 6 * 3},
                        {2, false, 1 + 4 * 3, 4 * 3}, {2, true, 1 + 6 * 3, 6 * 3}};
    for (const Row& row : rows) {
        const RobotSpec r = preset(row.type, row.middle);
        const BodyLayout L = make_body_layout(r);
        EXPECT_EQ(L.body_count, row.bodies) << r.name;
        EXPECT_EQ(L.joints.size(), static_cast<std::size_t>(row.joints)) << r.name;
        EXPECT_EQ(L.joints.size(), r.actuated().size());
        // One chassis per module, one panel per module except the centre.
        EXPECT_EQ(L.geoms.size(), 2 * r.modules.size() - 1);
        for (const LayoutJoint& j : L.joints) EXPECT_NE(j.chassis_body, j.panel_body);
    }
}

TEST(BodyLayout, GeometryOfOneHinge) {
    const BodyLayout L = make_body_layout(two_modules());
    ASSERT_EQ(L.body_count, 2);
    ASSERT_EQ(L.joints.size(), 1u);
    // Module b's panel sits 0.65 from b's centre towards a, on a's body.
    const LayoutGeom& panel = L.geoms[2];
    EXPECT_EQ(panel.kind, PartKind::Panel);
    EXPECT_EQ(panel.body, L.geoms[0].body);
    EXPECT_NEAR(panel.centre[0], kModulePitch - kPanelOffset, 1e-12);
    EXPECT_EQ(panel.size, (Vec3{kPanelThickness, 1, 1}));
    EXPECT_NEAR(L.body_mass[L.geoms[0].body], kChassisMass + kPanelMass, 1e-12);
    EXPECT_EQ(L.joints[0].anchor, L.geoms[1].centre);
    EXPECT_EQ(L.joints[0].panel_body, L.geoms[0].body);
    // Resting just above the ground.
    EXPECT_NEAR(L.geoms[0].centre[2], 0.5 + kStartClearance, 1e-12);
    // Recording parts: offsets from the body's centre of mass.
    const auto parts = L.parts();
    EXPECT_NEAR(parts[0].offset.pos[0], -(kPanelMass * (kModulePitch - kPanelOffset)) / (kChassisMass + kPanelMass), 1e-12);
}

TEST(Validate, RefusesBadRobotsClearly) {
    RobotSpec r = two_modules();
    EXPECT_EQ(problem_of(r), "");

    RobotSpec overlap = r;
    overlap.modules[1].cell = {0, 0, 0};
    EXPECT_NE(problem_of(overlap).find("overlapping cells"), std::string::npos) << problem_of(overlap);

    RobotSpec empty_target = r;
    empty_target.modules[1].attach = Dir::PosX;
    EXPECT_NE(problem_of(empty_target).find("to an empty cell"), std::string::npos);

    RobotSpec loose = r;
    loose.modules[1].attach = Dir::None;
    EXPECT_NE(problem_of(loose).find("disconnected modules"), std::string::npos);

    RobotSpec cycle = r;   // b -> c -> b, never reaching the centre a
    cycle.modules[0].cell = {5, 5, 5};
    cycle.modules.push_back({{2, 0, 0}, Axis::Y, Dir::NegX, "c"});
    cycle.modules[1].attach = Dir::PosX;
    EXPECT_NE(problem_of(cycle).find("cycle"), std::string::npos) << problem_of(cycle);

    RobotSpec no_centre = r;
    no_centre.centre = 7;
    EXPECT_NE(problem_of(no_centre).find("no centre"), std::string::npos);

    RobotSpec attached_centre = r;
    attached_centre.centre = 1;
    EXPECT_NE(problem_of(attached_centre).find("centre"), std::string::npos);

    RobotSpec hinged_centre = r;
    hinged_centre.modules[0].axis = Axis::X;
    EXPECT_NE(problem_of(hinged_centre).find("must be fixed"), std::string::npos);

    RobotSpec up = r;
    up.preferred = Axis::Z;
    EXPECT_NE(problem_of(up).find("preferred axis"), std::string::npos);

    RobotSpec none;
    EXPECT_NE(problem_of(none).find("no modules"), std::string::npos);
    EXPECT_THROW(make_body_layout(none), cic::InputError);
}

TEST(Names, RoundTripAndUnknown) {
    for (Axis a : {Axis::X, Axis::Y, Axis::Z, Axis::Fixed}) EXPECT_EQ(axis_from_name(to_string(a)), a);
    for (Dir d : {Dir::PosX, Dir::NegX, Dir::PosY, Dir::NegY, Dir::PosZ, Dir::NegZ, Dir::None})
        EXPECT_EQ(dir_from_name(to_string(d)), d);
    EXPECT_FALSE(axis_from_name("w"));
    EXPECT_FALSE(axis_from_name("X"));
    EXPECT_FALSE(dir_from_name("x"));
    EXPECT_EQ(neighbour({1, 2, 3}, Dir::NegZ), (Cell{1, 2, 2}));
    EXPECT_THROW(axis_vector(Axis::Fixed), std::invalid_argument);
}
