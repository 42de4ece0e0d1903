#pragma once
// Evolving for transfer (issue 55; docs/hypergp.md, "Evolving for transfer"):
// one HyperGP genotype scored on several bodies (Simulator.extraRobotFiles).
// A genotype fits any robot (its trees are queried at the body's modules), so
// each body builds its own controller from the same trees; each evaluation
// resets ODE's random state (sim::evaluate), so every body's score is the same
// whichever worker, and in whichever order, it runs.
#include <span>

#include "cic/io/settings.hpp"

namespace cic::hypergp {

// The aggregate of the bodies' fitnesses (after any penalty): their mean
// (summed in body order) or their minimum. Throws std::invalid_argument when empty.
double aggregate_fitness(std::span<const double> fitness, io::BodiesAggregate how);

} // namespace cic::hypergp
