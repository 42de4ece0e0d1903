#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "cic/gp/operators.hpp"
#include "support/tree_checks.hpp"

using namespace cic;
using namespace cic::gp;
using namespace cic::tree;
using cic::testing::caches_correct;

namespace {

PrimitiveSet wide_set() {
    return PrimitiveSet({{Op::Add, Op::Mul, Op::Atan, Op::Sin, Op::Gauss, Op::Div}, {}, 3, {1.0, -1.0}, true});
}

std::vector<Node> sorted_nodes(const Tree& a, const Tree& b) {
    std::vector<Node> all(a.nodes().begin(), a.nodes().end());
    all.insert(all.end(), b.nodes().begin(), b.nodes().end());
    for (Node& n : all) { n.size = 0; n.depth = 0; }
    std::sort(all.begin(), all.end(), [](const Node& x, const Node& y) {
        return std::tie(x.op, x.var, x.value) < std::tie(y.op, y.var, y.value);
    });
    return all;
}

} // namespace

TEST(PickNode, PrefersFunctionNodesNinetyPercent) {
    const Tree t = Tree::parse("(add (mul x0 x1) (sin x2))");   // 3 functions, 3 leaves
    Rng rng(1);
    int functions = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) functions += arity(t.nodes()[pick_node(rng, t)].op) > 0 ? 1 : 0;
    EXPECT_NEAR(functions / static_cast<double>(n), 0.9, 0.01);
    const Tree leaf = Tree::parse("x0");
    EXPECT_EQ(pick_node(rng, leaf), 0u);
    EXPECT_THROW(pick_node(rng, Tree()), std::invalid_argument);
}

TEST(PickNode, UniformPicksEveryNodeAlike) {
    const Tree t = Tree::parse("(add (mul x0 x1) (sin x2))");   // 6 nodes
    Rng rng(1);
    std::vector<int> count(t.size());
    const int n = 30000;
    for (int i = 0; i < n; ++i) ++count[pick_node(rng, t, NodeSelection::Uniform)];
    for (int c : count) EXPECT_NEAR(c / static_cast<double>(n), 1.0 / 6.0, 0.01);
    Rng a(4), b(4);
    for (int i = 0; i < 50; ++i)
        ASSERT_EQ(pick_node(a, t, NodeSelection::Uniform), pick_node(b, t, NodeSelection::Uniform));
    EXPECT_THROW(pick_node(rng, t, static_cast<NodeSelection>(7)), std::invalid_argument);
    EXPECT_THROW(pick_node(rng, Tree(), NodeSelection::Uniform), std::invalid_argument);
}

TEST(Mutation, SubtreesComeFromTheConfiguredGenerator) {
    // GP.mutationGenerator: Full grows exactly to the depth, Grow and PTC1 up to it.
    const PrimitiveSet ps = wide_set();
    Rng rng(6);
    const TreeGenerator full(ps, InitMethod::Full, 30, 1, 6);
    const TreeGenerator grow(ps, InitMethod::Grow, 30, 1, 6);
    const TreeGenerator ptc1(ps, InitMethod::Ptc1, 30, 1, 6);
    bool shallower = false;
    for (int n = 0; n < 300; ++n) {
        ASSERT_EQ(full.subtree(rng, 4).depth(), 4);
        ASSERT_LE(grow.subtree(rng, 4).depth(), 4);
        const int d = ptc1.subtree(rng, 4).depth();
        ASSERT_LE(d, 4);
        shallower = shallower || d < 4;
    }
    EXPECT_TRUE(shallower);
    // A leaf replaced by a Full subtree of depth 3 gives a tree of depth 3 + (its level - 1).
    const Tree leaf = Tree::parse("x0");
    EXPECT_EQ(mutate(rng, leaf, full, 3).depth(), 3);
    Rng a(9), b(9);
    EXPECT_EQ(mutate(a, leaf, full, 3, NodeSelection::Uniform), mutate(b, leaf, full, 3, NodeSelection::Uniform));
}

TEST(Mutation, ReplacesOneSubtreeWithABoundedGrowSubtree) {
    const PrimitiveSet ps = wide_set();
    const TreeGenerator gen(ps, InitMethod::Grow, 30, 1, 6);
    Rng rng(2);
    for (int n = 0; n < 500; ++n) {
        const Tree t = gen.generate(rng);
        const Tree m = mutate(rng, t, gen, 3);
        ASSERT_TRUE(caches_correct(m));
        ASSERT_LE(m.depth(), std::max(t.depth(), t.depth() - 1 + 3));
    }
}

TEST(Mutation, SameSeedSameChildAndBadArgumentsThrow) {
    const PrimitiveSet ps = wide_set();
    const TreeGenerator gen(ps, InitMethod::Grow, 30, 1, 6);
    Rng g(3);
    const Tree t = gen.full(g, 4);
    Rng a(10), b(10);
    for (int i = 0; i < 50; ++i) ASSERT_EQ(mutate(a, t, gen, 4), mutate(b, t, gen, 4));
    EXPECT_THROW(mutate(a, Tree(), gen, 4), std::invalid_argument);
    EXPECT_THROW(mutate(a, t, gen, 0), std::invalid_argument);
    EXPECT_THROW(mutate(a, Forest{}, gen, 4), std::invalid_argument);
}

TEST(Crossover, SwapsSubtreesAndConservesNodes) {
    const PrimitiveSet ps = wide_set();
    const TreeGenerator gen(ps, InitMethod::Grow, 30, 1, 6);
    Rng rng(4);
    for (int n = 0; n < 500; ++n) {
        const Tree a = gen.generate(rng), b = gen.generate(rng);
        const auto [c, d] = crossover(rng, a, b);
        ASSERT_TRUE(caches_correct(c));
        ASSERT_TRUE(caches_correct(d));
        ASSERT_EQ(c.size() + d.size(), a.size() + b.size());
        ASSERT_EQ(sorted_nodes(c, d), sorted_nodes(a, b));
    }
}

TEST(Crossover, SameSeedSameChildrenAndBadArgumentsThrow) {
    const Tree a = Tree::parse("(add (mul x0 x1) (sin x2))"), b = Tree::parse("(atan (add 1 x0))");
    Rng r1(5), r2(5);
    for (int i = 0; i < 50; ++i) ASSERT_EQ(crossover(r1, a, b), crossover(r2, a, b));
    EXPECT_THROW(crossover(r1, Tree(), b), std::invalid_argument);
    EXPECT_THROW(crossover(r1, Forest{a, b}, Forest{a}), std::invalid_argument);
    EXPECT_THROW(crossover(r1, Forest{}, Forest{}), std::invalid_argument);
}

TEST(Operators, CachesStayCorrectOverThousandsOfEdits) {
    const PrimitiveSet ps = wide_set();
    const TreeGenerator gen(ps, InitMethod::Ptc1, 15, 1, 8);
    Rng rng(6);
    std::vector<Tree> pool;
    for (int i = 0; i < 20; ++i) pool.push_back(gen.generate(rng));
    for (int step = 0; step < 4000; ++step) {
        const std::size_t i = rng.index(pool.size()), j = rng.index(pool.size());
        if (rng.bernoulli(0.5)) {
            pool[i] = mutate(rng, pool[i], gen, 4);
        } else {
            auto [c, d] = crossover(rng, pool[i], pool[j]);
            pool[i] = std::move(c);
            pool[j] = std::move(d);
        }
        if (pool[i].size() > 400) pool[i] = gen.generate(rng);   // keep the test fast
        ASSERT_TRUE(caches_correct(pool[i])) << "step " << step;
        ASSERT_TRUE(caches_correct(pool[j])) << "step " << step;
        ASSERT_EQ(Tree::parse(pool[i].to_string()), pool[i]);
    }
}

TEST(Operators, ForestOperatorsApplyTreeByTree) {
    const PrimitiveSet ps = wide_set();
    const TreeGenerator gen(ps, InitMethod::Full, 30, 1, 4);
    Rng g(7);
    Forest f, h;
    for (int i = 0; i < 4; ++i) {
        f.push_back(gen.full(g, 3));
        h.push_back(gen.full(g, 4));
    }
    // Mutating the forest equals mutating tree 0, then tree 1, ... with the same stream.
    Rng a(8), b(8);
    const Forest mf = mutate(a, f, gen, 3);
    ASSERT_EQ(mf.size(), 4u);
    for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(mf[k], mutate(b, f[k], gen, 3));
    Rng c(9), d(9);
    const auto [x, y] = crossover(c, f, h);
    for (std::size_t k = 0; k < 4; ++k) {
        const auto [xk, yk] = crossover(d, f[k], h[k]);
        EXPECT_EQ(x[k], xk);
        EXPECT_EQ(y[k], yk);
    }
}
