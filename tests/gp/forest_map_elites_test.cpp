// MAP-Elites over GP genotypes with HyperGP's own operators
// (gp/forest_map_elites.hpp) on a synthetic problem: bad arguments throw, the
// same seed gives the same archive, a restored checkpoint continues bit for
// bit, and children respect the depth cap.
#include <gtest/gtest.h>

#include "cic/gp/forest_map_elites.hpp"

namespace cic::gp {
namespace {

// Descriptor: the first tree's size and depth, scaled into [0, 1); fitness:
// minus the distance of the forest's total size from 15.
std::vector<Evaluation> synthetic(const std::vector<tree::Forest>& forests) {
    std::vector<Evaluation> out;
    for (const auto& f : forests) {
        Evaluation e;
        e.descriptor = {std::min(0.999, static_cast<double>(f[0].size()) / 40.0),
                        std::min(0.999, static_cast<double>(f[0].depth()) / 10.0)};
        e.fitness = -std::abs(static_cast<double>(tree::total_size(f)) - 15.0);
        out.push_back(e);
    }
    return out;
}

GpConfig gp_config() {
    GpConfig c;
    c.trees_per_genotype = 2;
    c.max_tree_depth = 8;
    return c;
}

MapElitesConfig config() { return {GridSpec{{8, 8}, {0, 0}, {1, 1}}, 20, 40}; }

TEST(ForestMapElites, BadArgumentsThrow) {
    const tree::PrimitiveSet ps(GpConfig{}.primitives);
    GpConfig none = gp_config();
    none.crossover_rate = 0;
    none.mutation_rate = 0;
    EXPECT_THROW(forest_emitter(none, ps), std::invalid_argument);
    MapElitesConfig bad = config();
    bad.initial = 0;
    EXPECT_THROW(MapElites<tree::Forest>(bad, forest_emitter(gp_config(), ps), 1), std::invalid_argument);
    EXPECT_THROW(MapElites<tree::Forest>(config(), Emitter<tree::Forest>{}, 1), std::invalid_argument);
    // A restored elite with another number of trees than the run makes.
    MapElites<tree::Forest> me(config(), forest_emitter(gp_config(), ps), 1);
    me.step(synthetic, 100);
    auto elites = me.archive().elites();
    elites.begin()->second.solution.pop_back();
    EXPECT_THROW(me.restore(elites, 20, 0, 1, Rng(1).state()), std::invalid_argument);
}

TEST(ForestMapElites, TheSameSeedGivesTheSameArchive) {
    const tree::PrimitiveSet ps(GpConfig{}.primitives);
    MapElites<tree::Forest> a(config(), forest_emitter(gp_config(), ps), 7),
        b(config(), forest_emitter(gp_config(), ps), 7), c(config(), forest_emitter(gp_config(), ps), 8);
    for (int i = 0; i < 8; ++i) {
        a.step(synthetic, 1000);
        b.step(synthetic, 1000);
        c.step(synthetic, 1000);
    }
    ASSERT_EQ(a.archive().filled(), b.archive().filled());
    for (const auto& [cell, e] : a.archive().elites()) EXPECT_EQ(b.archive().at(cell)->solution, e.solution);
    bool differs = a.archive().filled() != c.archive().filled();
    for (const auto& [cell, e] : a.archive().elites())
        differs = differs || !c.archive().at(cell) || !(c.archive().at(cell)->solution == e.solution);
    EXPECT_TRUE(differs);
}

TEST(ForestMapElites, ARestoredCheckpointContinuesBitForBit) {
    const tree::PrimitiveSet ps(GpConfig{}.primitives);
    MapElites<tree::Forest> whole(config(), forest_emitter(gp_config(), ps), 3);
    for (int i = 0; i < 4; ++i) whole.step(synthetic, 1000);
    const auto elites = whole.archive().elites();
    const long evaluations = whole.evaluations();
    const int batches = whole.batches();
    const Rng::State rng = whole.rng().state();
    for (int i = 0; i < 4; ++i) whole.step(synthetic, 1000);

    // The checkpoint as text and back, as a run's archive file holds it.
    std::map<std::size_t, GridArchive<tree::Forest>::Elite> reread;
    for (const auto& [cell, e] : elites) {
        tree::Forest f;
        for (const auto& t : e.solution) f.push_back(tree::Tree::parse(t.to_string()));
        reread.emplace(cell, GridArchive<tree::Forest>::Elite{e.descriptor, e.fitness, f});
    }
    MapElites<tree::Forest> resumed(config(), forest_emitter(gp_config(), ps), 999);
    resumed.restore(reread, evaluations, 0, batches, rng);
    for (int i = 0; i < 4; ++i) resumed.step(synthetic, 1000);
    ASSERT_EQ(resumed.archive().filled(), whole.archive().filled());
    for (const auto& [cell, e] : whole.archive().elites()) EXPECT_EQ(resumed.archive().at(cell)->solution, e.solution);
}

TEST(ForestMapElites, ChildrenKeepTheDepthCapAndFillTheGrid) {
    const tree::PrimitiveSet ps(GpConfig{}.primitives);
    GpConfig cfg = gp_config();
    cfg.max_tree_depth = 7;
    MapElites<tree::Forest> me(config(), forest_emitter(cfg, ps), 5);
    for (int i = 0; i < 30; ++i)
        me.step(
            [&](const std::vector<tree::Forest>& fs) {
                for (const auto& f : fs) EXPECT_LE(tree::max_depth(f), 7);
                return synthetic(fs);
            },
            1000);
    EXPECT_EQ(me.evaluations(), 600);
    EXPECT_GT(me.archive().filled(), 10u);
    EXPECT_EQ(me.archive().best()->fitness, 0.0);   // a forest of exactly 15 nodes was found
}

} // namespace
} // namespace cic::gp
