// Dynamic Limits (Silva & Costa; thesis 5.2). Depth is the individual's depth
// as GP.forestDepth measures it (by default the sum of its trees' depths, 7.2.1).
//
// Rules as implemented:
// - initialise: limit = depth of the best individual (>= 1); for Heavy also
//   >= initial_max, since "the minimum value of the limit is the maximum
//   allowed depth during initialization" (5.2.2). best_fitness = its fitness.
// - accept: a child within limit_for(parents) is accepted; a deeper one only
//   if its fitness beats the best so far, and then the limit rises to its depth.
// - limit_for: with an illegal parent, the larger parent depth (never less than
//   the current limit, so a stale mark cannot make the limit stricter).
// - end_generation: Simple never lowers the limit and marks nobody: illegals
//   arise only when a limit falls (5.2.1). Heavy lowers to the best's depth but
//   not below initial_max; VeryHeavy lowers to the best's depth (>= 1) (5.2.3).
//   Both then mark "illegal" = depth > limit. Callers also call it once after
//   initialise() so that deep initial individuals of the heavy variants get
//   their mark.
#include "cic/gp/bloat.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cic::gp {

namespace {
}

DynamicLimits::DynamicLimits(BloatVariant variant, int initial_max_depth, ForestDepth measure)
    : variant_(variant), measure_(measure) {
    if (initial_max_depth < 1)
        throw std::invalid_argument("DynamicLimits: initial maximum depth must be >= 1, got " +
                                    std::to_string(initial_max_depth));
    if (variant != BloatVariant::Simple && variant != BloatVariant::Heavy && variant != BloatVariant::VeryHeavy)
        throw std::invalid_argument("DynamicLimits: unknown variant");
    if (measure != ForestDepth::Sum && measure != ForestDepth::Max)
        throw std::invalid_argument("DynamicLimits: unknown forest depth measure");
    state_.initial_max = initial_max_depth;
}

void DynamicLimits::initialise(const Population& evaluated) {
    const Individual& best = evaluated.best();   // throws on an empty population
    if (!best.evaluated) throw std::invalid_argument("DynamicLimits::initialise: population is not evaluated");
    state_.limit = std::max(1, depth(best));
    if (variant_ == BloatVariant::Heavy) state_.limit = std::max(state_.limit, state_.initial_max);
    state_.best_fitness = best.fitness;
}

int DynamicLimits::limit_for(const Individual& p1, const Individual* p2) const {
    if (state_.limit <= 0) throw std::logic_error("DynamicLimits: used before initialise()");
    const bool illegal_parent = p1.illegal || (p2 && p2->illegal);
    if (!illegal_parent) return state_.limit;
    const int larger = std::max(depth(p1), p2 ? depth(*p2) : 0);
    return std::max(state_.limit, larger);
}

bool DynamicLimits::accept(const Individual& child, const Individual& p1, const Individual* p2) {
    const int limit = limit_for(p1, p2);
    const int d = depth(child);
    if (d <= limit) {
        if (child.evaluated && child.fitness > state_.best_fitness) state_.best_fitness = child.fitness;
        return true;
    }
    if (!child.evaluated)
        throw std::invalid_argument("DynamicLimits::accept: a child deeper than its limit must be evaluated first");
    if (child.fitness > state_.best_fitness) {
        state_.best_fitness = child.fitness;
        state_.limit = std::max(state_.limit, d);
        return true;
    }
    return false;
}

void DynamicLimits::end_generation(Population& pop) {
    if (state_.limit <= 0) throw std::logic_error("DynamicLimits: used before initialise()");
    if (!pop.empty()) {
        const Individual& best = pop.best();
        if (best.evaluated) state_.best_fitness = std::max(state_.best_fitness, best.fitness);
        if (variant_ != BloatVariant::Simple) {
            const int floor = variant_ == BloatVariant::Heavy ? state_.initial_max : 1;
            const int candidate = std::max(depth(best), floor);
            if (candidate < state_.limit) state_.limit = candidate;
        }
    }
    for (auto& p : pop) {
        if (!p) throw std::invalid_argument("DynamicLimits::end_generation: null individual");
        if (variant_ != BloatVariant::Simple && depth(*p) > state_.limit)
            p->illegal = true;
        else
            p->illegal = false;
    }
}

} // namespace cic::gp
