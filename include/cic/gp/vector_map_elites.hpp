#pragma once
// MAP-Elites over parameter vectors in the unit box (the gait experiment's
// encoding): uniform points first, then isotropic Gaussian mutation of elites
// drawn uniformly, clamped to [0, 1] (Mouret & Clune 2015; the line mutation
// of Vassiliades & Mouret 2018 is not used).
#include <cstdint>
#include <vector>

#include "cic/gp/map_elites.hpp"

namespace cic::gp {

struct VectorMapElitesConfig {
    GridSpec grid;
    std::size_t dimension = 0;   // parameters per solution
    int batch = 100;             // solutions evaluated together
    int initial = 100;           // uniform random solutions before any mutation
    double sigma = 0.1;          // the mutation's standard deviation, in the unit box

    // Throws std::invalid_argument naming the field.
    void validate() const;
};

using VectorBatch = MapElites<std::vector<double>>::Batch;

// The Gaussian emitter of `config` (its dimension and sigma).
Emitter<std::vector<double>> gaussian_emitter(const VectorMapElitesConfig& config);

class VectorMapElites : public MapElites<std::vector<double>> {
public:
    VectorMapElites(const VectorMapElitesConfig& config, std::uint64_t seed);
};

} // namespace cic::gp
