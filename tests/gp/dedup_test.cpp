#include <gtest/gtest.h>

#include <stdexcept>

#include "cic/gp/dedup.hpp"
#include "cic/gp/generators.hpp"

using namespace cic;
using namespace cic::gp;
using namespace cic::tree;

TEST(Dedup, SetComparesStructureExactly) {
    GenotypeSet set;
    const Forest a{Tree::parse("(add x0 1)")}, b{Tree::parse("(add x0 1.0000000000000002)")};
    EXPECT_TRUE(set.insert(a));
    EXPECT_FALSE(set.insert(Forest{Tree::parse("(add x0 1)")}));
    EXPECT_TRUE(set.insert(b));
    EXPECT_TRUE(set.contains(b));
    EXPECT_FALSE(set.contains(Forest{Tree::parse("(add 1 x0)")}));
    EXPECT_EQ(set.size(), 2u);
    set.clear();
    EXPECT_FALSE(set.contains(a));
}

TEST(Dedup, MakeUniqueRetriesBoundedly) {
    GenotypeSet set;
    int calls = 0;
    auto same = [&] { ++calls; return Forest{Tree::parse("x0")}; };
    bool unique = false;
    make_unique(set, 5, same, &unique);
    EXPECT_TRUE(unique);
    EXPECT_EQ(calls, 1);
    make_unique(set, 5, same, &unique);
    EXPECT_FALSE(unique);
    EXPECT_EQ(calls, 1 + 6);   // 1 + retries attempts, then the duplicate is accepted
    EXPECT_THROW(make_unique(set, -1, same), std::invalid_argument);
    EXPECT_THROW(make_unique(set, 1, {}), std::invalid_argument);
}

TEST(Dedup, GeneratedPopulationIsUniqueAndReproducible) {
    const PrimitiveSet ps(GpConfig{}.primitives);
    const TreeGenerator gen(ps, InitMethod::Ptc1, 10, 1, 6);
    auto build = [&](std::uint64_t seed) {
        Rng rng(seed);
        GenotypeSet set;
        std::vector<Forest> pop;
        for (int i = 0; i < 200; ++i) {
            bool unique = false;
            pop.push_back(make_unique(set, 50, [&] { return Forest{gen.generate(rng)}; }, &unique));
            EXPECT_TRUE(unique);
        }
        return pop;
    };
    const auto p = build(3);
    EXPECT_EQ(p, build(3));
    GenotypeSet check;
    for (const auto& f : p) EXPECT_TRUE(check.insert(f));
}
