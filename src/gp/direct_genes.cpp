// Direct genes beside the trees (Offset-HybrID; see GpConfig::DirectGenes).
#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cic/gp/dedup.hpp"
#include "cic/gp/operators.hpp"

namespace cic::gp {
namespace {

void check(const DirectGenes& cfg) {
    if (!(cfg.limit > 0) || !std::isfinite(cfg.limit))
        throw std::invalid_argument("direct genes: the limit must be finite and > 0");
    if (!(cfg.sigma >= 0) || !std::isfinite(cfg.sigma))
        throw std::invalid_argument("direct genes: sigma must be finite and >= 0");
    if (!(cfg.rate >= 0 && cfg.rate <= 1)) throw std::invalid_argument("direct genes: the rate must be in [0, 1]");
}

} // namespace

std::vector<double> initial_direct(Rng& rng, const DirectGenes& cfg) {
    check(cfg);
    std::vector<double> genes(cfg.count);
    for (double& g : genes) g = std::clamp(cfg.sigma * rng.normal(), -cfg.limit, cfg.limit);
    return genes;
}

std::vector<double> mutate_direct(Rng& rng, std::vector<double> genes, const DirectGenes& cfg) {
    check(cfg);
    if (genes.size() != cfg.count)
        throw std::invalid_argument("direct genes: " + std::to_string(genes.size()) + " genes, expected " +
                                    std::to_string(cfg.count));
    for (double& g : genes) {
        if (!std::isfinite(g)) throw std::invalid_argument("direct genes: a gene is not finite");
        if (rng.bernoulli(cfg.rate)) g = std::clamp(g + cfg.sigma * rng.normal(), -cfg.limit, cfg.limit);
    }
    return genes;
}

std::uint64_t genotype_hash(const tree::Forest& trees, std::span<const double> direct) {
    std::uint64_t h = tree::hash(trees);
    // +0.0 and -0.0 are one gene: they give every controller the same numbers.
    for (double g : direct) h = mix64(h ^ std::bit_cast<std::uint64_t>(g == 0 ? 0.0 : g)) + 0x9e3779b97f4a7c15ULL;
    return h;
}

} // namespace cic::gp
