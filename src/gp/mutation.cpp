// Subtree mutation (thesis 5.1.3) and the node picker shared with crossover.
#include <stdexcept>
#include <string>

#include "cic/gp/operators.hpp"

namespace cic::gp {

std::size_t pick_node(Rng& rng, const tree::Tree& t, NodeSelection how) {
    if (t.empty()) throw std::invalid_argument("pick_node: empty tree");
    const auto nodes = t.nodes();
    if (how == NodeSelection::Uniform) return rng.index(nodes.size());
    if (how != NodeSelection::Koza) throw std::invalid_argument("pick_node: unknown node selection");
    std::size_t functions = 0;
    for (const auto& n : nodes) functions += tree::arity(n.op) > 0 ? 1 : 0;   // inline table look-up
    // Koza's 90/10 rule: a function node with probability 0.9, else a leaf.
    const bool want_function = functions > 0 && rng.bernoulli(0.9);
    if (functions == 0) return rng.index(nodes.size());
    std::size_t k = rng.index(want_function ? functions : nodes.size() - functions);
    // The k-th (from 0) node of the wanted kind. Counting down without a branch on
    // the kind (which is unpredictable) leaves one well-predicted exit test.
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const std::size_t match = (tree::arity(nodes[i].op) > 0) == want_function ? 1 : 0;
        if (k < match) return i;   // k == 0 on a wanted node
        k -= match;
    }
    throw std::logic_error("pick_node: unreachable");
}

tree::Tree mutate(Rng& rng, const tree::Tree& t, const TreeGenerator& gen, int max_sub_depth,
                  NodeSelection how) {
    if (t.empty()) throw std::invalid_argument("mutate: empty tree");
    if (max_sub_depth < 1)
        throw std::invalid_argument("mutate: maximum subtree depth must be >= 1, got " + std::to_string(max_sub_depth));
    const std::size_t at = pick_node(rng, t, how);
    const tree::Tree sub = gen.subtree(rng, max_sub_depth);
    return t.replace_subtree(at, sub.nodes());
}

tree::Forest mutate(Rng& rng, const tree::Forest& f, const TreeGenerator& gen, int max_sub_depth,
                    NodeSelection how) {
    if (f.empty()) throw std::invalid_argument("mutate: empty forest");
    // Thesis 7.3.1: a new instance of the operator for each tree in turn.
    tree::Forest out;
    out.reserve(f.size());
    for (const auto& t : f) out.push_back(mutate(rng, t, gen, max_sub_depth, how));
    return out;
}

} // namespace cic::gp
