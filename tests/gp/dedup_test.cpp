#include <gtest/gtest.h>

#include "cic/gp/dedup.hpp"

using namespace cic;
using namespace cic::gp;
using namespace cic::tree;

TEST(Dedup, SeenGenotypesCompareStructure) {
    SeenGenotypes seen;
    const Forest a{Tree::parse("(add x0 1)")}, b{Tree::parse("(add x0 1.0000000000000002)")};
    EXPECT_TRUE(seen.insert(a));
    EXPECT_FALSE(seen.insert(Forest{Tree::parse("(add x0 1)")}));
    EXPECT_TRUE(seen.insert(b));   // constants compare by their bits
    EXPECT_TRUE(seen.contains(b));
    EXPECT_FALSE(seen.contains(Forest{Tree::parse("(add 1 x0)")}));   // argument order matters
    EXPECT_EQ(seen.size(), 2u);
    seen.clear();
    EXPECT_FALSE(seen.contains(a));
}

TEST(Dedup, AForestIsNotItsTreesInAnotherOrder) {
    SeenGenotypes seen;
    const Tree x = Tree::parse("x0"), y = Tree::parse("(mul x1 x1)");
    EXPECT_TRUE(seen.insert(Forest{x, y}));
    EXPECT_TRUE(seen.insert(Forest{y, x}));
    EXPECT_TRUE(seen.insert(Forest{x}));
    EXPECT_FALSE(seen.insert(Forest{x, y}));
}
