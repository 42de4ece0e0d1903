#pragma once
// Robots of any size for the scaling study (issue 38): a centipede is a fixed
// torso chain along y with P pairs of R1's three-module legs (hinges y, z, y
// from the hip out), preferred axis y, centre module torso.0 fixed.
//
// Layout: the torso has 2P - 1 cubes, y = -(P-1) .. P-1; pair k (k = 0 .. P-1,
// from -y to +y) sits on the torso cube y = 2k - (P-1), one leg along +x and
// one along -x. So legs are two cells apart, the torso has no cube past the
// end pairs, and the robot has 8P - 1 modules and 6P hinges (P = 2: 15
// modules, 12 hinges, the size of R1 with a shorter torso).
//
// The irregular twin: the -x legs of the front ceil(P/2) pairs (the pairs with
// the largest y) lack their last module (the tip's y hinge). The same quarter
// of the legs is short at every P (one leg at P = 1 and 2), so neither the
// left-right nor the front-back mirror maps the robot onto itself; it has
// 8P - 1 - ceil(P/2) modules and 6P - ceil(P/2) hinges.
#include "cic/sim/robot.hpp"

namespace cic::sim {

// The largest P whose regular centipede fits limits::kMaxModules.
int max_centipede_pairs();

// Throws std::invalid_argument when pairs is outside 1 .. max_centipede_pairs().
RobotSpec centipede(int pairs, bool irregular);

} // namespace cic::sim
