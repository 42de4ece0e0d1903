#include "cic/tree/tree.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cic/core/rng.hpp"

namespace cic::tree {

Node Node::constant(double v) {
    Node n;
    n.op = Op::Const;
    n.value = v;
    return n;
}

Node Node::variable(int index) {
    if (index < 0 || index > 65535)
        throw std::invalid_argument("variable index must be in [0, 65535], got " + std::to_string(index));
    Node n;
    n.op = Op::Var;
    n.var = static_cast<std::uint16_t>(index);
    return n;
}

Node Node::function(Op op) {
    if (arity(op) == 0) throw std::invalid_argument("Node::function: '" + std::string(name(op)) + "' is a terminal");
    Node n;
    n.op = op;
    return n;
}

namespace {

// Throws unless `nodes` is exactly one well-formed postfix tree.
void check_shape(std::span<const Node> nodes, const char* what) {
    if (nodes.empty()) throw std::invalid_argument(std::string(what) + ": empty node array");
    std::size_t stack = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const auto a = static_cast<std::size_t>(arity(nodes[i].op));  // throws on a bad op
        if (stack < a)
            throw std::invalid_argument(std::string(what) + ": node " + std::to_string(i) + " ('" +
                                        std::string(name(nodes[i].op)) + "') lacks arguments");
        stack = stack - a + 1;
    }
    if (stack != 1)
        throw std::invalid_argument(std::string(what) + ": " + std::to_string(stack) +
                                    " roots instead of one");
}

} // namespace

Tree::Tree(std::vector<Node> postfix) : nodes_(std::move(postfix)) { recompute_caches(); }

void Tree::recompute_caches() {
    check_shape(nodes_, "Tree");
    compute_caches(0, nodes_.size());
}

// Children of node i are found from the cached sizes of the nodes before it
// (last child at i - 1, each earlier one just before the previous one's
// subtree), so one forward sweep fills every cache without a stack.
void Tree::compute_caches(std::size_t from, std::size_t to) {
    Node* nodes = nodes_.data();
    for (std::size_t i = from; i < to; ++i) {
        Node& n = nodes[i];
        if (n.op != Op::Var) n.var = 0;        // canonical form, so == and hash() see structure only
        if (n.op != Op::Const) n.value = 0.0;
        if (n.op == Op::Const && !std::isfinite(n.value))
            throw std::invalid_argument("Tree: constant at node " + std::to_string(i) + " is not finite");
        const int a = arity(n.op);
        std::uint32_t size = 1;
        int depth = 0;
        std::size_t c = i;
        for (int k = 0; k < a; ++k) {
            c = k == 0 ? i - 1 : c - nodes[c].size;
            size += nodes[c].size;
            depth = std::max(depth, int{nodes[c].depth});
        }
        if (depth + 1 > 65535) throw std::invalid_argument("Tree: deeper than 65535 levels");
        n.size = size;
        n.depth = static_cast<std::uint16_t>(depth + 1);
    }
}

std::vector<std::size_t> Tree::children(std::size_t i) const {
    if (i >= nodes_.size()) throw std::out_of_range("Tree::children: node index out of range");
    const int a = arity(nodes_[i].op);
    std::vector<std::size_t> out(static_cast<std::size_t>(a));
    std::size_t c = i;  // walk back from the last child
    for (int k = a - 1; k >= 0; --k) {
        c = (k == a - 1) ? i - 1 : c - nodes_[c].size;
        out[static_cast<std::size_t>(k)] = c;
    }
    return out;
}

int Tree::depth_of_node(std::size_t i) const {
    if (i >= nodes_.size()) throw std::out_of_range("Tree::depth_of_node: node index out of range");
    std::size_t at = nodes_.size() - 1;
    int d = 1;
    while (at != i) {
        // Descend into the child whose range [begin, c] contains i.
        std::size_t c = at - 1;
        while (subtree_begin(c) > i) c -= nodes_[c].size;
        at = c;
        ++d;
    }
    return d;
}

std::span<const Node> Tree::subtree(std::size_t i) const {
    if (i >= nodes_.size()) throw std::out_of_range("Tree::subtree: node index out of range");
    const std::size_t b = subtree_begin(i);
    return std::span<const Node>(nodes_).subspan(b, i - b + 1);
}

Tree Tree::replace_subtree(std::size_t i, std::span<const Node> sub) const {
    if (i >= nodes_.size()) throw std::out_of_range("Tree::replace_subtree: node index out of range");
    check_shape(sub, "Tree::replace_subtree");
    const std::size_t b = subtree_begin(i);
    std::vector<Node> out;
    out.reserve(nodes_.size() - nodes_[i].size + sub.size());
    out.insert(out.end(), nodes_.begin(), nodes_.begin() + static_cast<long>(b));
    out.insert(out.end(), sub.begin(), sub.end());
    out.insert(out.end(), nodes_.begin() + static_cast<long>(i) + 1, nodes_.end());
    // The result is one tree (a valid prefix, one valid subtree, a valid suffix).
    // Caches change only in the new subtree and on the path above it: a suffix
    // node is an ancestor of node i exactly when its old subtree began at or
    // before b; every other node keeps its (already canonical) cache.
    Tree t;
    t.nodes_ = std::move(out);
    const std::size_t end = b + sub.size();
    t.compute_caches(b, end);
    const auto old_size = static_cast<std::int64_t>(nodes_[i].size);
    const std::int64_t delta = static_cast<std::int64_t>(sub.size()) - old_size;
    Node* nodes = t.nodes_.data();
    for (std::size_t j = end; j < t.nodes_.size(); ++j) {
        Node& n = nodes[j];
        const std::int64_t old_j = static_cast<std::int64_t>(j) - delta;
        if (old_j + 1 - static_cast<std::int64_t>(n.size) > static_cast<std::int64_t>(b)) continue;
        n.size = static_cast<std::uint32_t>(static_cast<std::int64_t>(n.size) + delta);
        int depth = 0;
        std::size_t c = j;
        for (int k = 0, a = arity(n.op); k < a; ++k) {
            c = k == 0 ? j - 1 : c - nodes[c].size;
            depth = std::max(depth, int{nodes[c].depth});
        }
        if (depth + 1 > 65535) throw std::invalid_argument("Tree: deeper than 65535 levels");
        n.depth = static_cast<std::uint16_t>(depth + 1);
    }
    return t;
}

std::uint64_t Tree::hash() const {
    std::uint64_t h = 0x51ed270b2f1c3a95ULL ^ nodes_.size();
    for (const Node& n : nodes_) {
        std::uint64_t w = static_cast<std::uint64_t>(n.op) | (std::uint64_t{n.var} << 8);
        h = mix64(h ^ w);
        if (n.op == Op::Const) {
            const double v = n.value == 0.0 ? 0.0 : n.value;  // -0.0 == 0.0, so hash them alike
            h = mix64(h ^ std::bit_cast<std::uint64_t>(v));
        }
    }
    return h;
}

std::uint64_t hash(const Forest& f) {
    std::uint64_t h = 0x2545f4914f6cdd1dULL ^ f.size();
    for (const Tree& t : f) h = mix64(h ^ t.hash());
    return h;
}

std::size_t total_size(const Forest& f) {
    std::size_t s = 0;
    for (const Tree& t : f) s += t.size();
    return s;
}

int total_depth(const Forest& f) {
    int d = 0;
    for (const Tree& t : f) d += t.depth();
    return d;
}

int max_depth(const Forest& f) {
    int d = 0;
    for (const Tree& t : f) d = std::max(d, t.depth());
    return d;
}

} // namespace cic::tree
