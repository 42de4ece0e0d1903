// MAP-Elites over unit-box vectors (gp/vector_map_elites.hpp) on a synthetic
// problem, with each emitter (Gaussian, Iso+LineDD): bad arguments throw, the
// same seed gives the same archive, and a restored checkpoint continues bit
// for bit; it illuminates the grid.
#include <gtest/gtest.h>

#include <cmath>

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

// Iso+LineDD with the paper's sigmas.
MapElites<std::vector<double>> iso_line(std::uint64_t seed, double line_sigma = 0.2) {
    VectorMapElitesConfig c = config();
    c.sigma = 0.01;
    return MapElites<std::vector<double>>(MapElitesConfig{c.grid, c.batch, c.initial}, iso_line_emitter(c, line_sigma),
                                          seed);
}

TEST(IsoLineEmitter, BadArgumentsThrow) {
    EXPECT_THROW(iso_line(1, -0.1), std::invalid_argument);
    EXPECT_THROW(iso_line(1, std::nan("")), std::invalid_argument);
    EXPECT_THROW(iso_line(1, HUGE_VAL), std::invalid_argument);
    auto bad = config();
    bad.sigma = 0;
    EXPECT_THROW(iso_line_emitter(bad, 0.2), std::invalid_argument);
    bad = config();
    bad.dimension = 0;
    EXPECT_THROW(iso_line_emitter(bad, 0.2), std::invalid_argument);
    const auto e = iso_line_emitter(config(), 0.2);
    EXPECT_THROW(e.check(std::vector<double>(4, 0.5)), std::invalid_argument);   // another dimension
    GridArchive<std::vector<double>> empty(config().grid);
    Rng rng(1);
    EXPECT_THROW(e.vary(rng, empty), std::logic_error);
}

TEST(IsoLineEmitter, TheSameSeedGivesTheSameArchiveAndTheLineStepMatters) {
    auto a = iso_line(7), b = iso_line(7), c = iso_line(8), flat = iso_line(7, 0.0);
    for (int i = 0; i < 10; ++i)
        for (auto* me : {&a, &b, &c, &flat}) me->step(synthetic, 1000);
    ASSERT_EQ(a.archive().filled(), b.archive().filled());
    for (const auto& [cell, e] : a.archive().elites()) EXPECT_EQ(b.archive().at(cell)->solution, e.solution);
    EXPECT_NE(a.archive().qd_score(-10), c.archive().qd_score(-10));
    EXPECT_NE(a.archive().qd_score(-10), flat.archive().qd_score(-10));
}

TEST(IsoLineEmitter, ARestoredCheckpointContinuesBitForBit) {
    auto whole = iso_line(3);
    for (int i = 0; i < 5; ++i) whole.step(synthetic, 10000);
    const auto elites = whole.archive().elites();
    const long evaluations = whole.evaluations(), failed = whole.failed();
    const int batches = whole.batches();
    const Rng::State rng = whole.rng().state();
    for (int i = 0; i < 5; ++i) whole.step(synthetic, 10000);

    auto resumed = iso_line(999);
    resumed.restore(elites, evaluations, failed, batches, rng);
    for (int i = 0; i < 5; ++i) resumed.step(synthetic, 10000);
    ASSERT_EQ(resumed.archive().filled(), whole.archive().filled());
    for (const auto& [cell, e] : whole.archive().elites()) {
        EXPECT_EQ(resumed.archive().at(cell)->solution, e.solution);
        EXPECT_EQ(resumed.archive().at(cell)->fitness, e.fitness);
    }
}

TEST(IsoLineEmitter, ItStaysInTheUnitBoxAndIlluminatesTheGrid) {
    auto me = iso_line(5);
    long budget = 2025;
    while (budget > 0) {
        const long before = me.evaluations();
        me.step(synthetic, budget);
        budget -= me.evaluations() - before;
    }
    for (const auto& [cell, e] : me.archive().elites())
        for (double v : e.solution) EXPECT_TRUE(v >= 0.0 && v <= 1.0) << v;
    EXPECT_GT(me.archive().coverage(), 0.9);
    EXPECT_GT(me.archive().best()->fitness, -0.02);
}

} // namespace
} // namespace cic::gp
