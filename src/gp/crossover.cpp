// One-point subtree crossover (thesis 5.1.4), tree by tree for forests (7.3.1).
#include <stdexcept>
#include <string>

#include "cic/gp/operators.hpp"

namespace cic::gp {

std::pair<tree::Tree, tree::Tree> crossover(Rng& rng, const tree::Tree& a, const tree::Tree& b, NodeSelection how) {
    if (a.empty() || b.empty()) throw std::invalid_argument("crossover: empty tree");
    const std::size_t i = pick_node(rng, a, how);
    const std::size_t j = pick_node(rng, b, how);
    return {a.replace_subtree(i, b.subtree(j)), b.replace_subtree(j, a.subtree(i))};
}

std::pair<tree::Forest, tree::Forest> crossover(Rng& rng, const tree::Forest& a, const tree::Forest& b,
                                                       NodeSelection how) {
    if (a.empty() || a.size() != b.size())
        throw std::invalid_argument("crossover: forests must be non-empty and of equal size, got " +
                                    std::to_string(a.size()) + " and " + std::to_string(b.size()) + " trees");
    std::pair<tree::Forest, tree::Forest> out;
    out.first.reserve(a.size());
    out.second.reserve(b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
        auto [x, y] = crossover(rng, a[k], b[k], how);
        out.first.push_back(std::move(x));
        out.second.push_back(std::move(y));
    }
    return out;
}

} // namespace cic::gp
