#pragma once
// Random trees for the tree-layer tests (the gp generators live a layer up).
#include <vector>

#include "cic/core/rng.hpp"
#include "cic/tree/tree.hpp"

namespace cic::tree::trees {

inline double random_constant(Rng& rng) {
    switch (rng.index(5)) {
    case 0: return rng.uniform(-1.0, 1.0);
    case 1: return rng.normal() * 1e12;
    case 2: return rng.normal() * 1e-300;
    case 3: return -0.0;
    default: return static_cast<double>(rng.between(-3, 3));
    }
}

// Appends a random tree of depth <= depth over every function and `vars` variables.
inline void random_nodes(Rng& rng, int depth, int vars, std::vector<Node>& out) {
    const auto fs = canonical_functions();
    if (depth <= 1 || rng.bernoulli(0.3)) {
        if (vars > 0 && rng.bernoulli(0.5))
            out.push_back(Node::variable(rng.between(0, vars - 1)));
        else
            out.push_back(Node::constant(random_constant(rng)));
        return;
    }
    const Op f = fs[rng.index(fs.size())];
    for (int c = 0; c < arity(f); ++c) random_nodes(rng, depth - 1, vars, out);
    out.push_back(Node::function(f));
}

inline Tree random_tree(Rng& rng, int depth, int vars) {
    std::vector<Node> nodes;
    random_nodes(rng, depth, vars, nodes);
    return Tree(std::move(nodes));
}

} // namespace cic::tree::trees
