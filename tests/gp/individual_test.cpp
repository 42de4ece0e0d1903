#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "cic/gp/individual.hpp"

using namespace cic::gp;
using namespace cic::tree;

namespace {
IndividualPtr make(std::uint64_t id, double fitness, const std::string& tree) {
    auto p = std::make_shared<Individual>();
    p->id = id;
    p->fitness = fitness;
    p->genotype = {Tree::parse(tree)};
    return p;
}
} // namespace

TEST(Individual, BetterOrdersByFitnessThenSizeThenId) {
    const auto big = make(1, 2.0, "(add x0 x1)"), small = make(2, 2.0, "x0"), worse = make(3, 1.0, "x0");
    const auto twin = make(4, 2.0, "x1");
    EXPECT_TRUE(better(*big, *worse));
    EXPECT_TRUE(better(*small, *big));
    EXPECT_TRUE(better(*small, *twin));
    EXPECT_FALSE(better(*twin, *small));
    EXPECT_FALSE(better(*small, *small));
    const auto nan = make(5, std::numeric_limits<double>::quiet_NaN(), "x0");
    EXPECT_TRUE(better(*worse, *nan));
    EXPECT_FALSE(better(*nan, *worse));
    EXPECT_EQ(big->size(), 3u);
    EXPECT_EQ(big->depth(ForestDepth::Sum), 2);
    EXPECT_EQ(big->depth(ForestDepth::Max), 2);
}

TEST(Population, BestUsesBetter) {
    Population pop;
    EXPECT_THROW(pop.best(), std::invalid_argument);
    pop.individuals = {make(1, 2.0, "(add x0 x1)"), make(7, 2.0, "x0"), make(3, 1.0, "x0"), make(2, 2.0, "x1")};
    EXPECT_EQ(pop.best().id, 2u);
    pop.individuals.push_back(nullptr);
    EXPECT_THROW(pop.best(), std::invalid_argument);
}
