#pragma once
// How a RobotSpec maps to rigid bodies, geoms and hinges, without ODE.
// Rigidly joined parts are contracted into one body: a module's panel is always
// part of its neighbour's body, and a Fixed module's chassis is part of its own
// panel's body. Each actuated module gives one hinge between the body carrying
// its chassis and the body carrying its panel (see docs/simulator.md).
#include <array>
#include <numbers>
#include <vector>

#include "cic/sim/recording.hpp"
#include "cic/sim/robot.hpp"

namespace cic::sim {

// The SSSA module of the reference simulator, in simulator units (m, kg).
inline constexpr double kModulePitch = 1.254;       // grid cell spacing
inline constexpr double kChassisSide = 1.0;
inline constexpr double kChassisMass = 1.0;
inline constexpr double kPanelThickness = 0.17;     // along the attach direction
inline constexpr double kPanelMass = 0.2;
inline constexpr double kPanelOffset = 0.65;        // panel centre from chassis centre
inline constexpr double kHingeLimit = std::numbers::pi / 2;
inline constexpr double kStartClearance = 0.01;     // lowest geom's gap above the ground at start

using Vec3 = std::array<double, 3>;

struct LayoutGeom {
    int body = 0;
    int module = 0;
    PartKind kind = PartKind::Chassis;
    Vec3 size{};
    Vec3 centre{};     // world position at the start pose (all boxes axis-aligned)
    double mass = 0.0;
};

struct LayoutJoint {
    int module = 0;
    int chassis_body = 0;   // body 1 of the hinge
    int panel_body = 0;     // body 2 of the hinge
    Axis axis = Axis::Y;
    Vec3 anchor{};          // the module's chassis centre, world, start pose
};

struct BodyLayout {
    int body_count = 0;
    std::vector<LayoutGeom> geoms;       // chassis of module i is geoms[chassis_geom[i]]
    std::vector<int> chassis_geom;       // per module
    std::vector<LayoutJoint> joints;     // in RobotSpec::actuated() order
    std::vector<double> body_mass;       // per body
    std::vector<Vec3> body_com;          // per body, world, start pose
    int centre_geom = 0;

    // Recording parts: every geom with its offset from its body's centre of mass.
    std::vector<Part> parts() const;
};

// Validates the robot (cic::InputError) and lays it out resting just above z = 0.
BodyLayout make_body_layout(const RobotSpec& robot);

Vec3 axis_vector(Axis a);   // unit vector; Fixed -> invalid_argument

} // namespace cic::sim
