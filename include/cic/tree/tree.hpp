#pragma once
// An expression tree stored as a postfix array (children before parent), as
// Operon does: evaluation is a linear sweep and subtree edits are splices.
// Every node caches its subtree size and depth, so reading them is O(1).
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cic/tree/primitives.hpp"

namespace cic::tree {

struct Node {
    Op op = Op::Const;
    std::uint16_t var = 0;      // variable index for Op::Var
    double value = 0.0;         // constant value for Op::Const
    std::uint32_t size = 1;     // nodes in the subtree rooted here (cached)
    std::uint16_t depth = 1;    // depth of the subtree rooted here; a leaf has depth 1 (cached)

    static Node constant(double v);
    static Node variable(int index);
    static Node function(Op op);
    bool operator==(const Node&) const = default;
};

class Tree {
public:
    Tree() = default;
    // Takes postfix nodes; recomputes size/depth caches; throws std::invalid_argument
    // if the array is not exactly one well-formed tree.
    explicit Tree(std::vector<Node> postfix);

    std::span<const Node> nodes() const { return nodes_; }
    bool empty() const { return nodes_.empty(); }
    std::size_t size() const { return nodes_.size(); }                     // O(1)
    int depth() const { return nodes_.empty() ? 0 : nodes_.back().depth; } // O(1)
    const Node& root() const { return nodes_.back(); }

    // Index i is a node; its subtree occupies [i - nodes[i].size + 1, i].
    std::size_t subtree_begin(std::size_t i) const { return i + 1 - nodes_[i].size; }
    int depth_of_node(std::size_t i) const;  // 1 for the root; O(size)
    std::vector<std::size_t> children(std::size_t i) const;

    // Replace the subtree at node i with `sub`; caches are updated.
    Tree replace_subtree(std::size_t i, std::span<const Node> sub) const;
    std::span<const Node> subtree(std::size_t i) const;

    // Structural hash and equality (exact constants).
    std::uint64_t hash() const;
    bool operator==(const Tree& other) const { return nodes_ == other.nodes_; }

    // S-expression: "(add (mul x0 x1) 1.5)"; constants printed with enough
    // digits to round-trip exactly ("%.17g"). Variables are x0..xN.
    std::string to_string() const;
    // Parses to_string()'s form. Throws cic::InputError naming the column.
    // `ps` (optional) restricts functions and variable indices.
    static Tree parse(std::string_view text, const PrimitiveSet* ps = nullptr);

private:
    void recompute_caches(); // validates shape too
    void compute_caches(std::size_t from, std::size_t to);  // caches of nodes [from, to); shape already valid
    std::vector<Node> nodes_;
};

// A genotype of one or more trees (thesis 7.3.1).
using Forest = std::vector<Tree>;
std::uint64_t hash(const Forest& f);
std::size_t total_size(const Forest& f);
int total_depth(const Forest& f);   // sum of depths (as thesis fig. 7.4b)
int max_depth(const Forest& f);

} // namespace cic::tree
