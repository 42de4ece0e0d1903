// One test per Dynamic Limits rule (thesis 5.2), on hand-built populations.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "cic/gp/bloat.hpp"

using namespace cic;
using namespace cic::gp;
using namespace cic::tree;

namespace {

// A tree of exactly `depth` levels: (neg (neg ... x0)).
Tree chain(int depth) {
    std::string text = "x0";
    for (int i = 1; i < depth; ++i) text = "(neg " + text + ")";
    return Tree::parse(text);
}

IndividualPtr make(std::uint64_t id, double fitness, int depth) {
    auto p = std::make_shared<Individual>();
    p->id = id;
    p->fitness = fitness;
    p->evaluated = true;
    p->genotype = {chain(depth)};
    return p;
}

Population population(std::initializer_list<std::pair<double, int>> fitness_depth) {
    Population pop;
    std::uint64_t id = 1;
    for (auto [f, d] : fitness_depth) pop.individuals.push_back(make(id++, f, d));
    return pop;
}

} // namespace

TEST(DynamicLimits, InitialLimitIsTheBestsDepth) {
    DynamicLimits dl(BloatVariant::Simple, 6);
    dl.initialise(population({{1.0, 3}, {5.0, 4}, {2.0, 6}}));
    EXPECT_EQ(dl.state().limit, 4);
    EXPECT_EQ(dl.state().best_fitness, 5.0);
    EXPECT_EQ(dl.state().initial_max, 6);
    // Heavy: the limit never starts below the initial maximum depth (5.2.2).
    DynamicLimits heavy(BloatVariant::Heavy, 6);
    heavy.initialise(population({{1.0, 3}, {5.0, 4}}));
    EXPECT_EQ(heavy.state().limit, 6);
}

TEST(DynamicLimits, ChildWithinTheLimitIsAlwaysAccepted) {
    DynamicLimits dl(BloatVariant::Simple, 6);
    Population pop = population({{5.0, 4}, {1.0, 2}});
    dl.initialise(pop);
    EXPECT_TRUE(dl.accept(*make(10, -100.0, 4), pop[0], &pop[1]));
    EXPECT_TRUE(dl.accept(*make(11, -100.0, 1), pop[0], nullptr));
    EXPECT_EQ(dl.state().limit, 4);
}

TEST(DynamicLimits, DeeperChildNeedsToBeatTheBestAndRaisesTheLimit) {
    DynamicLimits dl(BloatVariant::Simple, 6);
    Population pop = population({{5.0, 4}, {1.0, 2}});
    dl.initialise(pop);
    EXPECT_FALSE(dl.accept(*make(10, 5.0, 5), pop[0], &pop[1]));   // equal is not better
    EXPECT_EQ(dl.state().limit, 4);
    EXPECT_TRUE(dl.accept(*make(11, 5.5, 7), pop[0], &pop[1]));
    EXPECT_EQ(dl.state().limit, 7);
    EXPECT_EQ(dl.state().best_fitness, 5.5);
    // The best so far is remembered: 5.2 no longer passes at depth 8.
    EXPECT_FALSE(dl.accept(*make(12, 5.2, 8), pop[0], &pop[1]));
    // An unevaluated child deeper than its limit cannot be judged.
    auto raw = make(13, 0.0, 9);
    raw->evaluated = false;
    EXPECT_THROW(dl.accept(*raw, pop[0], &pop[1]), std::invalid_argument);
}

TEST(DynamicLimits, SimpleLimitOnlyRises) {
    DynamicLimits dl(BloatVariant::Simple, 2);
    Population pop = population({{5.0, 5}, {1.0, 3}});
    dl.initialise(pop);
    Population next = population({{9.0, 2}, {1.0, 5}});   // the best is now shallow
    dl.end_generation(next);
    EXPECT_EQ(dl.state().limit, 5);
    EXPECT_FALSE(next[0].illegal);
    EXPECT_FALSE(next[1].illegal);
}

TEST(DynamicLimits, HeavyFallsToTheBestsDepthButNotBelowInitialMax) {
    DynamicLimits dl(BloatVariant::Heavy, 4);
    Population pop = population({{5.0, 8}, {1.0, 3}});
    dl.initialise(pop);
    EXPECT_EQ(dl.state().limit, 8);
    Population next = population({{9.0, 6}, {1.0, 7}, {0.5, 5}});
    dl.end_generation(next);
    EXPECT_EQ(dl.state().limit, 6);              // fell to the best's depth
    EXPECT_TRUE(next[1].illegal);         // 7 > 6: now illegal
    EXPECT_FALSE(next[0].illegal);
    EXPECT_FALSE(next[2].illegal);
    Population shallow = population({{10.0, 2}, {1.0, 5}});
    dl.end_generation(shallow);
    EXPECT_EQ(dl.state().limit, 4);              // floor: the initial maximum depth
    EXPECT_TRUE(shallow[1].illegal);
}

TEST(DynamicLimits, VeryHeavyMayFallBelowInitialMax) {
    DynamicLimits dl(BloatVariant::VeryHeavy, 4);
    Population pop = population({{5.0, 6}, {1.0, 3}});
    dl.initialise(pop);
    Population shallow = population({{10.0, 2}, {1.0, 3}});
    dl.end_generation(shallow);
    EXPECT_EQ(dl.state().limit, 2);
    EXPECT_TRUE(shallow[1].illegal);
}

TEST(DynamicLimits, ChildOfAnIllegalParentGetsTheLargerParentsDepth) {
    DynamicLimits dl(BloatVariant::Heavy, 3);
    Population pop = population({{5.0, 9}, {1.0, 3}});
    dl.initialise(pop);
    Population next = population({{9.0, 4}, {1.0, 8}, {2.0, 3}});
    dl.end_generation(next);
    ASSERT_EQ(dl.state().limit, 4);
    ASSERT_TRUE(next[1].illegal);
    EXPECT_EQ(dl.limit_for(next[1], &next[2]), 8);   // illegal parent: larger parent depth
    EXPECT_EQ(dl.limit_for(next[2], &next[1]), 8);
    EXPECT_EQ(dl.limit_for(next[1], nullptr), 8);
    EXPECT_EQ(dl.limit_for(next[0], &next[2]), 4);   // legal parents: the current limit
    EXPECT_TRUE(dl.accept(*make(20, -1.0, 8), next[1], &next[2]));
    EXPECT_FALSE(dl.accept(*make(21, -1.0, 9), next[1], &next[2]));
    EXPECT_FALSE(dl.accept(*make(22, -1.0, 5), next[0], &next[2]));
    EXPECT_EQ(dl.state().limit, 4);                  // accepting an illegal's child does not raise it
}

TEST(DynamicLimits, RejectedChildIsSignalledForReplacement) {
    // accept() == false tells the caller to put a copy of a parent in the child's place.
    DynamicLimits dl(BloatVariant::Simple, 3);
    Population pop = population({{5.0, 3}, {4.0, 3}});
    dl.initialise(pop);
    const auto child = make(30, 1.0, 10);
    EXPECT_FALSE(dl.accept(*child, pop[0], &pop[1]));
    EXPECT_EQ(dl.state().limit, 3);
    EXPECT_EQ(dl.state().best_fitness, 5.0);
}

TEST(DynamicLimits, StateRoundTripsAndBadUseThrows) {
    EXPECT_THROW(DynamicLimits(BloatVariant::Simple, 0), std::invalid_argument);
    EXPECT_THROW(DynamicLimits(static_cast<BloatVariant>(9), 3), std::invalid_argument);
    DynamicLimits dl(BloatVariant::Heavy, 3);
    Population pop = population({{5.0, 3}});
    EXPECT_THROW(dl.limit_for(pop[0], nullptr), std::logic_error);
    EXPECT_THROW(dl.end_generation(pop), std::logic_error);
    EXPECT_THROW(dl.initialise(Population{}), std::invalid_argument);
    dl.initialise(pop);
    DynamicLimits copy(BloatVariant::Heavy, 3);
    copy.set_state(dl.state());
    EXPECT_EQ(copy.state().limit, dl.state().limit);
    EXPECT_EQ(copy.state().best_fitness, dl.state().best_fitness);
    EXPECT_EQ(copy.variant(), BloatVariant::Heavy);
}

namespace {

// One scripted generation: the population's (fitness, depth) pairs, and what
// the limit and the illegal marks must be after end_generation.
struct Generation {
    std::vector<std::pair<double, int>> individuals;
    int limit;
    std::vector<bool> illegal;
};

Population population(const std::vector<std::pair<double, int>>& fitness_depth) {
    Population pop;
    std::uint64_t id = 1;
    for (auto [f, d] : fitness_depth) pop.individuals.push_back(make(id++, f, d));
    return pop;
}

// Drives `dl` through the script: initialise on the first generation, then
// end_generation on each, checking the limit and every mark as it goes.
void run_script(DynamicLimits& dl, const std::vector<Generation>& script) {
    for (std::size_t g = 0; g < script.size(); ++g) {
        SCOPED_TRACE("generation " + std::to_string(g));
        Population pop = population(script[g].individuals);
        if (g == 0) dl.initialise(pop);
        dl.end_generation(pop);
        EXPECT_EQ(dl.state().limit, script[g].limit);
        for (std::size_t i = 0; i < pop.size(); ++i)
            EXPECT_EQ(pop[i].illegal, script[g].illegal[i]) << "individual " << i;
    }
}

} // namespace

// Thesis 5.2: the simple limit starts at the best's depth, never falls, and
// nobody is ever illegal, however deep.
TEST(DynamicLimitsScript, SimpleNeverFallsAndHasNoIllegals) {
    DynamicLimits dl(BloatVariant::Simple, 7);
    run_script(dl, {
                       {{{3.0, 5}, {1.0, 9}, {2.0, 7}}, 5, {false, false, false}},
                       {{{4.0, 3}, {1.0, 12}}, 5, {false, false}},    // best shallower: no fall
                       {{{5.0, 2}, {0.0, 6}}, 5, {false, false}},
                   });
    // A deeper child that beats the best raises it for good.
    Population pop = population({{5.0, 2}});
    EXPECT_TRUE(dl.accept(*make(50, 6.0, 8), pop[0], nullptr));
    EXPECT_EQ(dl.state().limit, 8);
    Population next = population({{6.0, 8}, {1.0, 9}});
    dl.end_generation(next);
    EXPECT_EQ(dl.state().limit, 8);
    EXPECT_FALSE(next[1].illegal);
    // The child of a deep parent is held to the limit, not to its parent's depth.
    EXPECT_EQ(dl.limit_for(next[1], nullptr), 8);
}

// 5.2.1-5.2.2: the heavy limit follows the best's depth down, never below the
// initial maximum depth; whoever is deeper is illegal until it is not.
TEST(DynamicLimitsScript, HeavyFallsToTheBestButNotBelowTheInitialMaximum) {
    DynamicLimits dl(BloatVariant::Heavy, 7);
    run_script(dl, {
                       {{{3.0, 10}, {1.0, 12}, {2.0, 7}}, 10, {false, true, false}},
                       {{{4.0, 9}, {1.0, 10}, {0.5, 8}}, 9, {false, true, false}},
                       {{{5.0, 3}, {1.0, 8}, {0.5, 7}}, 7, {false, true, false}},   // floor 7
                       {{{6.0, 2}, {1.0, 7}}, 7, {false, false}},
                   });
    // A child of an illegal parent is held to the larger parent's depth.
    Population pop = population({{6.0, 2}, {1.0, 9}});
    pop[1].illegal = true;
    EXPECT_EQ(dl.limit_for(pop[0], &pop[1]), 9);
    EXPECT_TRUE(dl.accept(*make(60, 0.0, 9), pop[0], &pop[1]));
    EXPECT_FALSE(dl.accept(*make(61, 0.0, 10), pop[0], &pop[1]));
    EXPECT_EQ(dl.limit_for(pop[0], nullptr), 7);
}

// 5.2.3: the very heavy limit may fall below the initial maximum depth.
TEST(DynamicLimitsScript, VeryHeavyFallsBelowTheInitialMaximum) {
    DynamicLimits dl(BloatVariant::VeryHeavy, 7);
    run_script(dl, {
                       {{{3.0, 10}, {1.0, 12}}, 10, {false, true}},
                       {{{5.0, 3}, {1.0, 8}, {0.5, 3}}, 3, {false, true, false}},
                       {{{6.0, 1}, {1.0, 2}}, 1, {false, true}},
                       {{{7.0, 4}, {1.0, 2}}, 1, {true, true}},   // never rises at a generation's end
                   });
}

// Thesis 7.2.1: a forest is as deep as the sum of its trees, unless asked otherwise.
TEST(DynamicLimits, ForestDepthIsTheSumOfTheTreesByDefault) {
    auto forest = [](double fitness, std::vector<int> depths) {
        auto p = make(1, fitness, 1);
        p->genotype.clear();
        for (int d : depths) p->genotype.push_back(chain(d));
        return p;
    };
    Population pop;
    pop.individuals = {forest(5.0, {3, 4, 2, 1})};
    DynamicLimits by_sum(BloatVariant::Simple, 4 * 7);
    by_sum.initialise(pop);
    EXPECT_EQ(by_sum.state().limit, 10);
    DynamicLimits by_max(BloatVariant::Simple, 7, ForestDepth::Max);
    by_max.initialise(pop);
    EXPECT_EQ(by_max.state().limit, 4);
    // A child with trees 4+4+2+1 = 11 deep by sum breaks the sum limit, not the max one.
    const auto child = forest(1.0, {4, 4, 2, 1});
    EXPECT_FALSE(by_sum.accept(*child, pop[0], nullptr));
    EXPECT_TRUE(by_max.accept(*child, pop[0], nullptr));
    EXPECT_THROW(DynamicLimits(BloatVariant::Simple, 7, static_cast<ForestDepth>(5)), std::invalid_argument);
    // A 1-tree genotype has one depth whichever the measure.
    EXPECT_EQ(make(2, 0.0, 6)->depth(ForestDepth::Sum), make(2, 0.0, 6)->depth(ForestDepth::Max));
}

// The heavy floor is the deepest genotype initialisation can make, in the same measure.
TEST(DynamicLimits, InitialMaximumFollowsTheSettings) {
    GpConfig cfg;   // PTC1, maximum depth 6 counted from a root of depth 0: 7 levels
    EXPECT_EQ(cfg.generated_tree_levels(), 7);
    cfg.trees_per_genotype = 4;
    EXPECT_EQ(cfg.generated_forest_depth(), 28);
    cfg.forest_depth = ForestDepth::Max;
    EXPECT_EQ(cfg.generated_forest_depth(), 7);
    cfg.ptc1_root_depth = 1;
    EXPECT_EQ(cfg.generated_tree_levels(), 6);
    cfg.ptc1_root_depth = 0;
    cfg.init_method = InitMethod::Grow;   // Grow counts a leaf as 1, as the thesis's pseudocode
    EXPECT_EQ(cfg.generated_tree_levels(), 6);
}
