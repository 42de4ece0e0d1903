#pragma once
// The bodies of a run beyond its robot (issue 55, "Evolving for transfer";
// docs/hypergp.md): several bodies in one fitness (Simulator.extraRobotFiles)
// and a growing robot (Simulator.growRobotFiles, growAt), as facts of the
// settings that validation, the search, checkpoints and replays all read.
#include <cstddef>

#include "cic/io/settings.hpp"

namespace cic::io {

// Simulator.extraRobotFiles given: each genotype is scored on several bodies.
bool several_bodies(const Settings& s);
// Simulator.growRobotFiles given: the run's body changes along its budget.
bool grows(const Settings& s);
// The bodies a growing robot passes through, its robot first (1 when it does not grow).
std::size_t growing_bodies(const Settings& s);
// The first generation evaluated on body `body` (>= 1) of a growing robot:
// the first whose share of the budget reaches growAt[body - 1], that is
// ceil(growAt[body - 1] * Control.maximumIterations) (a share that rounds to
// a whole generation within 1e-9 counts as that generation).
int grow_generation(const Settings& s, std::size_t body);
// The body (0 = the robot) that generation `generation` is evaluated on.
std::size_t body_of_generation(const Settings& s, int generation);

} // namespace cic::io
