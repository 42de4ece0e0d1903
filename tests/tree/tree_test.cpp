#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "cic/tree/tree.hpp"
#include "support/random_trees.hpp"
#include "support/tree_checks.hpp"

using namespace cic;
using namespace cic::tree;

namespace {

// (add (mul x0 x1) (sin 1.5)) in postfix.
Tree sample() {
    return Tree({Node::variable(0), Node::variable(1), Node::function(Op::Mul), Node::constant(1.5),
                 Node::function(Op::Sin), Node::function(Op::Add)});
}

} // namespace

TEST(Tree, CachesSizeAndDepth) {
    const Tree t = sample();
    EXPECT_EQ(t.size(), 6u);
    EXPECT_EQ(t.depth(), 3);
    EXPECT_EQ(t.root().op, Op::Add);
    EXPECT_EQ(t.nodes()[2].size, 3u);
    EXPECT_EQ(t.nodes()[4].depth, 2);
    EXPECT_TRUE(cic::testing::caches_correct(t));
    EXPECT_EQ(Tree({Node::constant(2.0)}).depth(), 1);
    EXPECT_EQ(Tree().depth(), 0);
    EXPECT_TRUE(Tree().empty());
}

TEST(Tree, ConstructionRejectsMalformedArrays) {
    EXPECT_THROW(Tree(std::vector<Node>{}), std::invalid_argument);
    EXPECT_THROW(Tree({Node::function(Op::Add)}), std::invalid_argument);
    EXPECT_THROW(Tree({Node::variable(0), Node::function(Op::Add)}), std::invalid_argument);
    EXPECT_THROW(Tree({Node::variable(0), Node::variable(1)}), std::invalid_argument);
    EXPECT_THROW(Tree({Node::constant(std::numeric_limits<double>::quiet_NaN())}), std::invalid_argument);
    Node bad;
    bad.op = static_cast<Op>(99);
    EXPECT_THROW(Tree({bad}), std::invalid_argument);
    EXPECT_THROW(Node::function(Op::Var), std::invalid_argument);
    EXPECT_THROW(Node::variable(-1), std::invalid_argument);
    EXPECT_THROW(Node::variable(70000), std::invalid_argument);
}

TEST(Tree, ConstructionNormalisesAndRecomputesCaches) {
    Node n = Node::variable(3);
    n.size = 77;
    n.depth = 9;
    n.value = 4.0;   // meaningless for a variable
    const Tree t({n});
    EXPECT_EQ(t.root().size, 1u);
    EXPECT_EQ(t.root().depth, 1);
    EXPECT_EQ(t, Tree({Node::variable(3)}));
}

TEST(Tree, ChildrenSubtreeAndNodeDepth) {
    const Tree t = sample();
    EXPECT_EQ(t.children(5), (std::vector<std::size_t>{2, 4}));
    EXPECT_EQ(t.children(2), (std::vector<std::size_t>{0, 1}));
    EXPECT_EQ(t.children(4), (std::vector<std::size_t>{3}));
    EXPECT_TRUE(t.children(0).empty());
    EXPECT_EQ(t.subtree_begin(4), 3u);
    EXPECT_EQ(t.subtree(2).size(), 3u);
    const int expected[] = {3, 3, 2, 3, 2, 1};
    for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(t.depth_of_node(i), expected[i]) << i;
    EXPECT_THROW(t.children(6), std::out_of_range);
    EXPECT_THROW(t.subtree(6), std::out_of_range);
    EXPECT_THROW(t.depth_of_node(6), std::out_of_range);
}

TEST(Tree, NodeDepthMatchesAWalkOnRandomTrees) {
    Rng rng(5);
    for (int n = 0; n < 200; ++n) {
        const Tree t = trees::random_tree(rng, 8, 3);
        // depth_of_node(i) + depth of i's subtree - 1 <= tree depth, with equality on a deepest path.
        int deepest = 0;
        for (std::size_t i = 0; i < t.size(); ++i) {
            const int d = t.depth_of_node(i);
            ASSERT_LE(d + t.nodes()[i].depth - 1, t.depth());
            if (arity(t.nodes()[i].op) == 0) deepest = std::max(deepest, d);
            for (std::size_t c : t.children(i)) ASSERT_EQ(t.depth_of_node(c), d + 1);
        }
        ASSERT_EQ(deepest, t.depth());
    }
}

TEST(Tree, ReplaceSubtreeSplicesAndUpdatesCaches) {
    const Tree t = sample();
    const Tree sub({Node::variable(2), Node::function(Op::Neg), Node::function(Op::Neg)});
    const Tree r = t.replace_subtree(0, sub.nodes());   // x0 -> (neg (neg x2))
    EXPECT_EQ(r.to_string(), "(add (mul (neg (neg x2)) x1) (sin 1.5))");
    EXPECT_EQ(r.size(), 8u);
    EXPECT_EQ(r.depth(), 5);
    EXPECT_TRUE(cic::testing::caches_correct(r));
    const Tree whole = t.replace_subtree(5, sub.nodes());
    EXPECT_EQ(whole, sub);
    EXPECT_EQ(t.size(), 6u);   // the original is unchanged
    EXPECT_THROW(t.replace_subtree(6, sub.nodes()), std::out_of_range);
    const Node broken[] = {Node::variable(0), Node::function(Op::Add)};
    EXPECT_THROW(t.replace_subtree(0, broken), std::invalid_argument);
    const Node two[] = {Node::variable(0), Node::variable(1)};
    EXPECT_THROW(t.replace_subtree(0, two), std::invalid_argument);
    // Net effect +1 but not a tree on its own: must not be accepted.
    const Node sneaky[] = {Node::function(Op::Neg)};
    EXPECT_THROW(t.replace_subtree(3, sneaky), std::invalid_argument);
}

TEST(Tree, HashAndEqualityAreStructural) {
    const Tree a = sample();
    EXPECT_EQ(a.hash(), sample().hash());
    EXPECT_EQ(a, sample());
    const Tree b = a.replace_subtree(3, Tree({Node::constant(1.5000000000000002)}).nodes());
    EXPECT_NE(a, b);
    EXPECT_NE(a.hash(), b.hash());
    const Tree c = a.replace_subtree(0, Tree({Node::variable(1)}).nodes());
    EXPECT_NE(a.hash(), c.hash());
    EXPECT_EQ(Tree({Node::constant(0.0)}).hash(), Tree({Node::constant(-0.0)}).hash());
    Rng rng(9);
    std::vector<std::uint64_t> hashes;
    for (int i = 0; i < 500; ++i) {
        const Tree t = trees::random_tree(rng, 6, 4);
        if (t.size() > 3) hashes.push_back(t.hash());
    }
    std::sort(hashes.begin(), hashes.end());
    EXPECT_GT(std::unique(hashes.begin(), hashes.end()) - hashes.begin(), static_cast<long>(hashes.size() * 9 / 10));
}

TEST(Tree, ForestHelpers) {
    const Forest f{sample(), Tree({Node::variable(0)})};
    EXPECT_EQ(total_size(f), 7u);
    EXPECT_EQ(total_depth(f), 4);
    EXPECT_EQ(max_depth(f), 3);
    const Forest g{Tree({Node::variable(0)}), sample()};
    EXPECT_NE(hash(f), hash(g));   // order matters
    EXPECT_EQ(hash(f), hash(Forest{sample(), Tree({Node::variable(0)})}));
    EXPECT_EQ(total_size(Forest{}), 0u);
}
