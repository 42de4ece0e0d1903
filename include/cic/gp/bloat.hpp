#pragma once
// Dynamic Limits bloat control (Silva & Costa; thesis 5.2): simple, heavy and
// very heavy variants, with illegal individuals.
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
    DynamicLimits(BloatVariant variant, int initial_max_depth);

    // After the first evaluation: limit = depth of the best individual (at least 1).
    void initialise(const Population& evaluated);

    // The limit that applies to a child of these parents: if a parent is illegal
    // (marked "illegal"), the larger parent depth; else the current limit.
    int limit_for(const Individual& p1, const Individual* p2) const;

    // Decide on an evaluated child. Accepts if depth <= limit_for(parents); a
    // deeper child is accepted only if its fitness beats the best so far, and
    // then the limit rises to its depth. Returns false when the child must be
    // replaced by a copy of a parent.
    bool accept(const Individual& child, const Individual& p1, const Individual* p2);

    // End of generation: Heavy/VeryHeavy may lower the limit to the best's depth
    // (Heavy never below initial_max); individuals deeper than the limit are marked
    // "illegal", the others have the mark removed.
    void end_generation(Population& pop);

    const BloatState& state() const { return state_; }
    void set_state(const BloatState& s) { state_ = s; }
    BloatVariant variant() const { return variant_; }

private:
    BloatVariant variant_;
    BloatState state_;
};

} // namespace cic::gp
