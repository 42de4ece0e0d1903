#pragma once
// MAP-Elites over GP genotypes: HyperGP's own operators as the emitter. A new
// genotype comes from the configured generator (PTC1 by default, with the
// initial population's depths); a varied one from one-point subtree crossover
// of two elites drawn uniformly from the archive (the first child kept), with
// probability crossoverRate / (crossoverRate + mutationRate), else from subtree
// mutation of one elite (the run's mutation generator and depth). There is no
// tournament, no parsimony and no Dynamic Limits: the archive is the
// selection, and a child with a tree deeper than GP.maximumTreeDepth (when it
// is not 0) is varied again, at most GP.duplicateRetries times, then replaced
// by a new genotype. Reproduction is not used: a copy of an elite could only
// tie it.
#include "cic/gp/config.hpp"
#include "cic/gp/map_elites.hpp"
#include "cic/tree/primitives.hpp"
#include "cic/tree/tree.hpp"

namespace cic::gp {

// Throws std::invalid_argument for crossover and mutation rates that are both 0.
// The primitive set must outlive the emitter.
Emitter<tree::Forest> forest_emitter(const GpConfig& config, const tree::PrimitiveSet& primitives);

} // namespace cic::gp
