#include "cic/gp/vector_map_elites.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cic::gp {

void MapElitesConfig::validate() const {
    grid.validate();
    if (batch < 1) throw std::invalid_argument("map-elites: batch must be at least 1");
    if (initial < 1) throw std::invalid_argument("map-elites: initial must be at least 1");
}

void VectorMapElitesConfig::validate() const {
    MapElitesConfig{grid, batch, initial}.validate();
    if (dimension < 1) throw std::invalid_argument("map-elites: dimension must be at least 1");
    if (!(sigma > 0) || !std::isfinite(sigma)) throw std::invalid_argument("map-elites: sigma must be a number > 0");
}

namespace {

// Uniform points to start, and the dimension check; `vary` is the emitter's own.
Emitter<std::vector<double>> unit_box_emitter(const VectorMapElitesConfig& config) {
    config.validate();
    const std::size_t n = config.dimension;
    Emitter<std::vector<double>> e;
    e.random = [n](Rng& rng) {
        std::vector<double> x(n);
        for (double& v : x) v = rng.uniform();
        return x;
    };
    e.check = [n](const std::vector<double>& x) {
        if (x.size() != n)
            throw std::invalid_argument("map-elites: an elite of " + std::to_string(x.size()) +
                                        " parameters for a dimension of " + std::to_string(n));
    };
    return e;
}

} // namespace

Emitter<std::vector<double>> gaussian_emitter(const VectorMapElitesConfig& config) {
    Emitter<std::vector<double>> e = unit_box_emitter(config);
    e.vary = [sigma = config.sigma](Rng& rng, const GridArchive<std::vector<double>>& archive) {
        std::vector<double> x = archive.at(archive.random_cell(rng))->solution;
        for (double& v : x) v = std::clamp(v + sigma * rng.normal(), 0.0, 1.0);
        return x;
    };
    return e;
}

Emitter<std::vector<double>> iso_line_emitter(const VectorMapElitesConfig& config, double line_sigma) {
    if (!(line_sigma >= 0) || !std::isfinite(line_sigma))
        throw std::invalid_argument("map-elites: the line sigma must be a number >= 0");
    Emitter<std::vector<double>> e = unit_box_emitter(config);
    e.vary = [iso = config.sigma, line_sigma](Rng& rng, const GridArchive<std::vector<double>>& archive) {
        // Two elites drawn independently (the same one twice leaves only the
        // isotropic part, as in the paper's sampling with replacement).
        const std::vector<double>& xi = archive.at(archive.random_cell(rng))->solution;
        const std::vector<double>& xj = archive.at(archive.random_cell(rng))->solution;
        const double along = line_sigma * rng.normal();
        std::vector<double> x(xi.size());
        for (std::size_t k = 0; k < x.size(); ++k)
            x[k] = std::clamp(xi[k] + iso * rng.normal() + along * (xj[k] - xi[k]), 0.0, 1.0);
        return x;
    };
    return e;
}

VectorMapElites::VectorMapElites(const VectorMapElitesConfig& config, std::uint64_t seed)
    : MapElites(MapElitesConfig{config.grid, config.batch, config.initial}, gaussian_emitter(config), seed) {}

} // namespace cic::gp
