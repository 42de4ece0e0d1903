#pragma once
// CMA-ME's improvement emitter for gait vectors (MapElites.emitter = cma-me;
// cma_me_emitter.cpp says how it works). A built-in of the emitter registry
// (experiments/map_elites_emitters.cpp).
#include <vector>

#include "cic/gp/map_elites.hpp"
#include "cic/gp/vector_map_elites.hpp"
#include "cic/io/settings.hpp"

namespace cic::gait {

// The emitter: its CMA-ES population is config.batch, its first step size
// config.sigma, seeded from the run's seed.
gp::Emitter<std::vector<double>> cma_me_emitter(const io::Settings& s, const gp::VectorMapElitesConfig& config);
// Throws cic::InputError for MapElites settings it cannot run with: a batch
// below pagmo's 5, or an initial count that is not a whole number of batches.
void check_cma_me(const io::Settings& s);

} // namespace cic::gait
