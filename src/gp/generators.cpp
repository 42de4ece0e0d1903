// Tree generators (thesis 6.3.4). Trees are emitted straight into postfix
// order: a function is chosen first, then its children are generated, then
// the function node is appended after them.
#include "cic/gp/generators.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace cic::gp {

using tree::Node;
using tree::Op;
using tree::Tree;

namespace {

constexpr int kMaxAttempts = 10000;   // bounded regeneration for the minimum depth

double sum(const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x;
    return s;
}

// Picks an index with probability weights[i] / total.
std::size_t weighted(Rng& rng, const std::vector<double>& weights, double total) {
    double r = rng.uniform() * total;
    for (std::size_t i = 0; i + 1 < weights.size(); ++i) {
        if (r < weights[i]) return i;
        r -= weights[i];
    }
    return weights.size() - 1;
}

} // namespace

TreeGenerator::TreeGenerator(const tree::PrimitiveSet& ps, InitMethod method, double expected_size,
                             int min_depth, int max_depth)
    : ps_(ps), method_(method), expected_size_(expected_size), min_depth_(min_depth), max_depth_(max_depth) {
    if (max_depth < 1 || max_depth > 65535)
        throw std::invalid_argument("tree generator: maximum depth must be in [1, 65535], got " +
                                    std::to_string(max_depth));
    if (min_depth < 1 || min_depth > max_depth)
        throw std::invalid_argument("tree generator: minimum depth must be in [1, " + std::to_string(max_depth) +
                                    "], got " + std::to_string(min_depth));
    if (!ps.has_terminals()) throw std::invalid_argument("tree generator: the primitive set has no terminals");
    if (!(expected_size >= 1.0) || !std::isfinite(expected_size))
        throw std::invalid_argument("tree generator: expected tree size must be >= 1, got " +
                                    std::to_string(expected_size));
    // PTC1, eq. 6.4: p = (1 - 1/E) / sum_f q_f b_f with q normalised.
    const auto& cfg = ps.config();
    const double total = sum(cfg.function_weights);
    double branching = 0.0;
    for (std::size_t i = 0; i < cfg.functions.size(); ++i)
        branching += cfg.function_weights[i] / total * tree::arity(cfg.functions[i]);
    p_function_ = (1.0 - 1.0 / expected_size) / branching;
    if (method == InitMethod::Ptc1 && !(p_function_ >= 0.0 && p_function_ <= 1.0))
        throw std::invalid_argument("tree generator: PTC1 cannot reach expected size " +
                                    std::to_string(expected_size) + " with this function set (p = " +
                                    std::to_string(p_function_) + " > 1)");
}

Node TreeGenerator::random_function(Rng& rng) const {
    const auto& cfg = ps_.config();
    return Node::function(cfg.functions[weighted(rng, cfg.function_weights, sum(cfg.function_weights))]);
}

Node TreeGenerator::random_terminal(Rng& rng) const {
    const auto& cfg = ps_.config();
    const double vars = cfg.variable_count * cfg.variable_weight;
    const double consts = static_cast<double>(cfg.constants.size() + (cfg.ephemeral ? 1 : 0)) * cfg.constant_weight;
    if (vars > 0.0 && rng.uniform() * (vars + consts) < vars)
        return Node::variable(static_cast<int>(rng.index(static_cast<std::size_t>(cfg.variable_count))));
    const std::size_t k = rng.index(cfg.constants.size() + (cfg.ephemeral ? 1 : 0));
    if (k < cfg.constants.size()) return Node::constant(cfg.constants[k]);
    return Node::constant(rng.uniform(cfg.ephemeral_min, cfg.ephemeral_max));   // ephemeral constant
}

namespace {

// kind(level) says whether to place a function at this level (1 = root).
template <class Kind>
void build(Rng& rng, int level, int max_depth, const Kind& kind, std::vector<Node>& out,
           const TreeGenerator& gen, Node (TreeGenerator::*fn)(Rng&) const,
           Node (TreeGenerator::*term)(Rng&) const) {
    if (level >= max_depth || !kind(rng)) {
        out.push_back((gen.*term)(rng));
        return;
    }
    const Node f = (gen.*fn)(rng);
    for (int c = 0; c < tree::arity(f.op); ++c) build(rng, level + 1, max_depth, kind, out, gen, fn, term);
    out.push_back(f);
}

// Room for a full binary tree up to depth 5, so small trees (mutation's subtrees)
// are built without re-allocating.
std::size_t initial_capacity(int max_depth) { return (std::size_t{1} << std::min(max_depth, 5)) - 1; }

void check_depth(int d, const char* who) {
    if (d < 1 || d > 65535)
        throw std::invalid_argument(std::string(who) + ": depth must be in [1, 65535], got " + std::to_string(d));
}

} // namespace

tree::Tree TreeGenerator::grow(Rng& rng, int max_depth) const {
    check_depth(max_depth, "grow");
    // Grow draws from all nodes A = F + T alike, so a function with probability |F| / |A|.
    const auto nf = static_cast<double>(ps_.config().functions.size());
    const double p = nf / (nf + static_cast<double>(ps_.terminal_count()));
    std::vector<Node> out;
    out.reserve(initial_capacity(max_depth));
    build(rng, 1, max_depth, [p](Rng& r) { return r.bernoulli(p); }, out, *this, &TreeGenerator::random_function,
          &TreeGenerator::random_terminal);
    return Tree(std::move(out));
}

tree::Tree TreeGenerator::full(Rng& rng, int depth) const {
    check_depth(depth, "full");
    std::vector<Node> out;
    out.reserve(initial_capacity(depth));
    build(rng, 1, depth, [](Rng&) { return true; }, out, *this, &TreeGenerator::random_function,
          &TreeGenerator::random_terminal);
    return Tree(std::move(out));
}

tree::Tree TreeGenerator::ptc1(Rng& rng, int max_depth) const {
    check_depth(max_depth, "ptc1");
    if (!(p_function_ >= 0.0 && p_function_ <= 1.0))
        throw std::invalid_argument("ptc1: expected size unreachable with this function set");
    const double p = p_function_;
    std::vector<Node> out;
    out.reserve(initial_capacity(max_depth));
    build(rng, 1, max_depth, [p](Rng& r) { return r.bernoulli(p); }, out, *this, &TreeGenerator::random_function,
          &TreeGenerator::random_terminal);
    return Tree(std::move(out));
}

tree::Tree TreeGenerator::subtree(Rng& rng, int max_depth) const {
    switch (method_) {
    case InitMethod::Full: return full(rng, max_depth);
    case InitMethod::Ptc1: return ptc1(rng, max_depth);
    case InitMethod::Grow:
    case InitMethod::RampedHalfAndHalf: return grow(rng, max_depth);
    }
    throw std::invalid_argument("subtree: unknown generation method");
}

tree::Tree TreeGenerator::generate(Rng& rng, std::size_t slot, std::size_t slots) const {
    if (slots == 0 || slot >= slots)
        throw std::invalid_argument("generate: slot " + std::to_string(slot) + " is not below slots " +
                                    std::to_string(slots));
    auto within = [&](auto make) {
        for (int attempt = 0; attempt < kMaxAttempts; ++attempt) {
            Tree t = make();
            if (t.depth() >= min_depth_) return t;
        }
        throw std::runtime_error("tree generator: no tree reached the minimum depth " + std::to_string(min_depth_) +
                                 " in " + std::to_string(kMaxAttempts) +
                                 " attempts; lower the minimum depth or raise the expected size");
    };
    switch (method_) {
    case InitMethod::Full: return full(rng, max_depth_);
    case InitMethod::Grow: return within([&] { return grow(rng, max_depth_); });
    case InitMethod::Ptc1: return within([&] { return ptc1(rng, max_depth_); });
    case InitMethod::RampedHalfAndHalf: {
        // Thesis 6.3.4.3: even slots Grow to the maximum depth; odd slots Full with
        // depths ramping evenly from the minimum to the maximum depth.
        if (slot % 2 == 0) return within([&] { return grow(rng, max_depth_); });
        const std::size_t fulls = slots / 2;
        const std::size_t ramp = static_cast<std::size_t>(max_depth_ - min_depth_ + 1);
        const int depth = min_depth_ + static_cast<int>((slot / 2) * ramp / fulls);
        return full(rng, depth);
    }
    }
    throw std::invalid_argument("generate: unknown initialisation method");
}

} // namespace cic::gp
