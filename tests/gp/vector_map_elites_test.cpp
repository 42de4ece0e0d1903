// MAP-Elites over unit-box vectors (gp/vector_map_elites.hpp) on a synthetic
// problem: bad arguments throw, the same seed gives the same archive, and a
// restored checkpoint continues bit for bit; it illuminates the grid.
#include <gtest/gtest.h>

#include "cic/gp/vector_map_elites.hpp"

namespace cic::gp {
namespace {

// Descriptor: the first two parameters; fitness: closeness of the rest to 0.3.
// Every 17th solution fails, as a blown-up simulation would.
std::vector<Evaluation> synthetic(const std::vector<std::vector<double>>& xs) {
    std::vector<Evaluation> out;
    for (const auto& x : xs) {
        Evaluation e;
        e.descriptor = {x[0], x[1]};
        for (std::size_t i = 2; i < x.size(); ++i) e.fitness -= (x[i] - 0.3) * (x[i] - 0.3);
        e.failed = static_cast<int>(x[2] * 1e6) % 17 == 0;
        out.push_back(e);
    }
    return out;
}

VectorMapElitesConfig config() {
    VectorMapElitesConfig c;
    c.grid = GridSpec{{10, 10}, {0, 0}, {1, 1}};
    c.dimension = 5;
    c.batch = 50;
    c.initial = 100;
    c.sigma = 0.1;
    return c;
}

TEST(VectorMapElites, BadArgumentsThrow) {
    auto bad = config();
    bad.dimension = 0;
    EXPECT_THROW(VectorMapElites(bad, 1), std::invalid_argument);
    bad = config();
    bad.batch = 0;
    EXPECT_THROW(VectorMapElites(bad, 1), std::invalid_argument);
    bad = config();
    bad.sigma = 0;
    EXPECT_THROW(VectorMapElites(bad, 1), std::invalid_argument);
    bad = config();
    bad.grid.bins = {10};
    EXPECT_THROW(VectorMapElites(bad, 1), std::invalid_argument);
    VectorMapElites me(config(), 1);
    EXPECT_THROW(me.step(synthetic, 0), std::invalid_argument);
    EXPECT_THROW(me.step([](const auto&) { return std::vector<Evaluation>{}; }, 100), std::logic_error);
    EXPECT_THROW(me.restore({}, 5, 6, 1, Rng(1).state()), std::invalid_argument);
}

TEST(VectorMapElites, TheSameSeedGivesTheSameArchive) {
    VectorMapElites a(config(), 7), b(config(), 7), c(config(), 8);
    for (int i = 0; i < 10; ++i) {
        a.step(synthetic, 1000);
        b.step(synthetic, 1000);
        c.step(synthetic, 1000);
    }
    ASSERT_EQ(a.archive().filled(), b.archive().filled());
    for (const auto& [cell, e] : a.archive().elites()) EXPECT_EQ(b.archive().at(cell)->solution, e.solution);
    EXPECT_NE(a.archive().qd_score(-10), c.archive().qd_score(-10));
}

TEST(VectorMapElites, ARestoredCheckpointContinuesBitForBit) {
    VectorMapElites whole(config(), 3);
    for (int i = 0; i < 5; ++i) whole.step(synthetic, 10000);
    const auto elites = whole.archive().elites();
    const long evaluations = whole.evaluations(), failed = whole.failed();
    const int batches = whole.batches();
    const Rng::State rng = whole.rng().state();
    for (int i = 0; i < 5; ++i) whole.step(synthetic, 10000);

    VectorMapElites resumed(config(), 999);   // the seed is the checkpoint's, not this one
    resumed.restore(elites, evaluations, failed, batches, rng);
    for (int i = 0; i < 5; ++i) resumed.step(synthetic, 10000);
    EXPECT_EQ(resumed.evaluations(), whole.evaluations());
    EXPECT_EQ(resumed.failed(), whole.failed());
    ASSERT_EQ(resumed.archive().filled(), whole.archive().filled());
    for (const auto& [cell, e] : whole.archive().elites()) {
        EXPECT_EQ(resumed.archive().at(cell)->solution, e.solution);
        EXPECT_EQ(resumed.archive().at(cell)->fitness, e.fitness);
    }
}

TEST(VectorMapElites, ItIlluminatesTheGridWithinTheBudget) {
    VectorMapElites me(config(), 5);
    long budget = 2025;
    while (budget > 0) {
        const long before = me.evaluations();
        me.step(synthetic, budget);
        budget -= me.evaluations() - before;
    }
    EXPECT_EQ(me.evaluations(), 2025);   // the last batch is cut to the budget
    EXPECT_GT(me.failed(), 0);
    EXPECT_GT(me.archive().coverage(), 0.9);
    // Mutation improves on the uniform start: the best is close to the optimum 0.
    EXPECT_GT(me.archive().best()->fitness, -0.02);
}

} // namespace
} // namespace cic::gp
