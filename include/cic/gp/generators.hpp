#pragma once
// Tree generators (thesis 6.3.4): Grow, Full, Ramped half-and-half, PTC1 (Luke 2000).
// Depth convention: a single leaf has depth 1.
#include "cic/core/rng.hpp"
#include "cic/gp/config.hpp"
#include "cic/tree/tree.hpp"

namespace cic::gp {

class TreeGenerator {
public:
    // Throws std::invalid_argument on bad limits (min > max, max < 1, no terminals,
    // expected size < 1, PTC1 p outside [0,1]).
    TreeGenerator(const tree::PrimitiveSet& ps, InitMethod method, double expected_size,
                  int min_depth, int max_depth);

    tree::Tree grow(Rng& rng, int max_depth) const;
    tree::Tree full(Rng& rng, int depth) const;
    tree::Tree ptc1(Rng& rng, int max_depth) const;
    // One tree by the configured method, regenerated (boundedly) until it reaches
    // the minimum depth. `slot`/`slots` ramp depths for RHH.
    tree::Tree generate(Rng& rng, std::size_t slot = 0, std::size_t slots = 1) const;
    // A subtree for mutation: at most max_depth levels by the configured method
    // (Full: exactly max_depth; Grow, PTC1 and RHH's Grow half: up to it), no minimum.
    tree::Tree subtree(Rng& rng, int max_depth) const;
    const tree::PrimitiveSet& primitives() const { return ps_; }
    double function_probability() const { return p_function_; }  // PTC1's p (eq. 6.4)

private:
    tree::Node random_terminal(Rng& rng) const;
    tree::Node random_function(Rng& rng) const;
    const tree::PrimitiveSet& ps_;
    InitMethod method_;
    double expected_size_;
    int min_depth_, max_depth_;
    double p_function_ = 0.0;
};

} // namespace cic::gp
