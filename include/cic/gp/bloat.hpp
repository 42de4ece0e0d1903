#pragma once
// Dynamic Limits bloat control (Silva & Costa; thesis 5.2): simple, heavy and
// very heavy variants; illegal individuals in the heavy ones.
#include "cic/gp/config.hpp"
#include "cic/gp/individual.hpp"

namespace cic::gp {

struct BloatState {
    int limit = 0;          // the current dynamic depth limit; 0 = not yet initialised
    int initial_max = 0;    // maximum depth of initialisation (floor for Heavy)
    double best_fitness = 0.0;  // fitness of the best individual seen so far
};

class DynamicLimits {
public:
    // `initial_max_depth` is the deepest genotype the initialisation can make,
    // measured as `measure` measures every depth here.
    DynamicLimits(BloatVariant variant, int initial_max_depth, ForestDepth measure = ForestDepth::Sum);

    // After the first evaluation: limit = depth of the best individual (at least 1;
    // Heavy: at least initial_max).
    void initialise(const Population& evaluated);

    // The limit that applies to a child of these parents: with an illegal parent
    // (heavy variants only), the larger parent depth; else the current limit.
    int limit_for(const Individual& p1, const Individual* p2) const;

    // Decide on an evaluated child. Accepts if depth <= limit_for(parents); a
    // deeper child is accepted only if its fitness beats the best so far, and
    // then the limit rises to its depth. Returns false when the child must be
    // replaced by a copy of a parent.
    bool accept(const Individual& child, const Individual& p1, const Individual* p2);

    // End of generation. Simple: the limit never falls and nobody is illegal.
    // Heavy/VeryHeavy: the limit falls to the best's depth (Heavy never below
    // initial_max); individuals deeper than it are marked illegal, the others
    // lose the mark.
    void end_generation(Population& pop);

    int depth(const Individual& ind) const { return ind.depth(measure_); }
    const BloatState& state() const { return state_; }
    void set_state(const BloatState& s) { state_ = s; }
    BloatVariant variant() const { return variant_; }

private:
    BloatVariant variant_;
    ForestDepth measure_;
    BloatState state_;
};

} // namespace cic::gp
