#pragma once
// MAP-Elites over parameter vectors in the unit box (the gait experiment's
// encoding): uniform points first, then variation of elites drawn uniformly,
// clamped to [0, 1]. Two emitters: isotropic Gaussian mutation of one elite
// (Mouret & Clune 2015), and Iso+LineDD (Vassiliades & Mouret, GECCO 2018):
//   x' = x_i + sigma_iso N(0, I) + sigma_line N(0, 1) (x_j - x_i),
// two elites i and j, which moves along the directions in which the elites
// already differ (the correlations of the elite hypervolume).
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
// Iso+LineDD: config.sigma is sigma_iso, `line_sigma` sigma_line (the paper's
// 0.01 and 0.2). Throws std::invalid_argument for a line_sigma < 0 or not finite.
Emitter<std::vector<double>> iso_line_emitter(const VectorMapElitesConfig& config, double line_sigma);

class VectorMapElites : public MapElites<std::vector<double>> {
public:
    VectorMapElites(const VectorMapElitesConfig& config, std::uint64_t seed);
};

} // namespace cic::gp
