// Parent selection (thesis 5.1.2): tournament with lexicographic parsimony, roulette.
#include <cmath>
#include <stdexcept>
#include <string>

#include "cic/gp/operators.hpp"

namespace cic::gp {

namespace {

const Individual& at(std::span<const IndividualPtr> pop, std::size_t i) {
    if (!pop[i]) throw std::invalid_argument("selection: null individual at index " + std::to_string(i));
    return *pop[i];
}

} // namespace

std::size_t tournament(Rng& rng, std::span<const IndividualPtr> pop, int k, bool parsimony) {
    if (pop.empty()) throw std::invalid_argument("tournament: empty population");
    if (k < 1) throw std::invalid_argument("tournament: size must be >= 1, got " + std::to_string(k));
    std::size_t winner = rng.index(pop.size());
    for (int round = 1; round < k; ++round) {
        const std::size_t c = rng.index(pop.size());
        const Individual& a = at(pop, c);
        const Individual& w = at(pop, winner);
        // Lexicographic parsimony (Luke & Panait): equal fitness -> the smaller genotype.
        if (a.fitness > w.fitness || (parsimony && a.fitness == w.fitness && a.size() < w.size())) winner = c;
    }
    at(pop, winner);
    return winner;
}

std::size_t roulette(Rng& rng, std::span<const IndividualPtr> pop) {
    if (pop.empty()) throw std::invalid_argument("roulette: empty population");
    double lowest = 0.0;
    for (std::size_t i = 0; i < pop.size(); ++i) {
        const double f = at(pop, i).fitness;
        if (!std::isfinite(f))
            throw std::invalid_argument("roulette: fitness of individual " + std::to_string(i) + " is not finite");
        lowest = i == 0 ? f : std::min(lowest, f);
    }
    // Shift so every weight is positive: the worst keeps a tiny chance (1e-12).
    const double shift = lowest <= 0.0 ? 1e-12 - lowest : 0.0;
    double total = 0.0;
    for (const auto& p : pop) total += p->fitness + shift;
    double r = rng.uniform() * total;
    for (std::size_t i = 0; i + 1 < pop.size(); ++i) {
        const double w = pop[i]->fitness + shift;
        if (r < w) return i;
        r -= w;
    }
    return pop.size() - 1;
}

std::size_t select(Rng& rng, std::span<const IndividualPtr> pop, const GpConfig& cfg) {
    switch (cfg.selection) {
    case SelectionType::Tournament: return tournament(rng, pop, cfg.tournament_size, cfg.lexicographic_parsimony);
    case SelectionType::Roulette: return roulette(rng, pop);
    }
    throw std::invalid_argument("select: unknown selection type");
}

} // namespace cic::gp
