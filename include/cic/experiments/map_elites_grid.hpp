#pragma once
// The MAP-Elites grid a run's settings make for its robot (MapElites.*):
//   duty-factor  one dimension per branch end (sim::branch_ends: the legs'
//                feet), each over [0, 1] in MapElites.bins bins;
//   omni         x and y displacement, each over [-omniRange, omniRange].
#include "cic/gp/grid_archive.hpp"
#include "cic/io/settings.hpp"
#include "cic/sim/robot.hpp"

namespace cic::experiments {

// Throws cic::InputError naming the MapElites keys: a robot without a branch
// end for duty factors, or more cells than an archive holds.
gp::GridSpec map_elites_grid(const io::Settings& s, const sim::RobotSpec& robot);

} // namespace cic::experiments
