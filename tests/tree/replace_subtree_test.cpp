// replace_subtree updates caches only on the splice and the path above it;
// the result must equal a tree built from scratch from the same nodes.
#include <gtest/gtest.h>

#include <vector>

#include "cic/core/rng.hpp"
#include "support/random_trees.hpp"

using namespace cic;
using namespace cic::tree;

TEST(ReplaceSubtree, CachesEqualAFullRecomputeOnRandomSplices) {
    Rng rng(77);
    for (int n = 0; n < 3000; ++n) {
        const Tree t = trees::random_tree(rng, 1 + static_cast<int>(rng.index(9)), 3);
        const Tree donor = trees::random_tree(rng, 1 + static_cast<int>(rng.index(7)), 3);
        const std::size_t at = rng.index(t.size());
        const std::size_t from = rng.index(donor.size());
        const Tree r = t.replace_subtree(at, donor.subtree(from));
        const Tree fresh(std::vector<Node>(r.nodes().begin(), r.nodes().end()));
        ASSERT_EQ(r, fresh) << t.to_string() << " at " << at << " <- " << donor.to_string() << " at " << from;
        ASSERT_EQ(r.size(), t.size() - t.nodes()[at].size + donor.nodes()[from].size);
    }
}

TEST(ReplaceSubtree, RawNodesWithStaleCachesAreRecomputed) {
    // A caller's span may carry wrong caches and non-canonical fields: they are fixed.
    const Tree t = Tree::parse("(add (mul x0 x1) (sin 1.5))");
    Node neg = Node::function(Op::Neg);
    neg.size = 9;
    neg.depth = 40;
    neg.value = 3.0;
    Node x = Node::variable(2);
    x.size = 5;
    const Node sub[] = {x, neg};
    const Tree r = t.replace_subtree(1, sub);
    EXPECT_EQ(r.to_string(), "(add (mul x0 (neg x2)) (sin 1.5))");
    EXPECT_EQ(r, Tree(std::vector<Node>(r.nodes().begin(), r.nodes().end())));
    EXPECT_EQ(r.depth(), 4);
    EXPECT_EQ(r.size(), 7u);
}
