#pragma once
// Robot description -> substrate geometry (thesis 3.3, fig. 3.1): the neurons
// sit where the modules are, so any robot file gets a matching network.
#include "cic/nn/config.hpp"
#include "cic/nn/geometry.hpp"
#include "cic/sim/robot.hpp"

namespace cic::hypergp {

// Grid (x, y) of every module, normalised per axis over the robot's bounding
// box to [-1, 1]: u = (2x - x_min - x_max) / (x_max - x_min) (exactly
// antisymmetric about the box centre, so mirrored modules get exactly
// opposite coordinates); an axis with
// x_min == x_max maps to 0. z is ignored (the CPPF sees the plan view).
//   joints: one per actuated module, in RobotSpec::actuated() order;
//   hidden: one per distinct (x, y) module position, in module order.
// Throws cic::InputError (via RobotSpec::validate) for an invalid robot and
// std::invalid_argument for a robot without actuated modules.
nn::Geometry substrate_geometry(const sim::RobotSpec& robot);
// The same in the layout Neural.substrateLayout names: normalised (the above,
// the default) or absolute: (x - x_c, y - y_c) / substrateUnit, cells counted
// from the robot's centre module c, so that a bigger body keeps the spacing
// between neighbouring legs and is queried beyond the smaller one's range.
nn::Geometry substrate_geometry(const sim::RobotSpec& robot, const nn::NeuralConfig& cfg);

} // namespace cic::hypergp
