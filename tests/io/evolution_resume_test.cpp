// The generational loop: determinism, exact resume, elitism and stop rules.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "cic/gp/evolution.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/tree/eval.hpp"
#include "support/gp_fixtures.hpp"

namespace cic::gp {
namespace {

using cic::testing::QuadraticEvaluator;
using cic::testing::small_gp_config;

struct Run {
    EvolutionResult result;
    std::vector<std::string> checkpoints;   // population text per generation
    std::vector<GenerationRecord> records;
};

io::PopulationFile header_for(const GpConfig& c) {
    io::PopulationFile h;
    h.experiment = "test";
    h.variables = c.primitives.variable_count;
    h.trees = c.trees_per_genotype;
    return h;
}

Run run(const GpConfig& c, const BloatConfig& b, int generations, std::uint64_t seed,
        std::optional<io::PopulationFile> from = std::nullopt) {
    tree::PrimitiveSet ps(c.primitives);
    QuadraticEvaluator eval;
    Run out;
    EvolutionState st;
    st.seed = seed;
    st.rng = Rng(seed);
    std::optional<Population> start;
    if (from) {
        st = from->state;
        start = from->population;
    }
    EvolutionHooks hooks;
    hooks.on_generation = [&](const GenerationRecord& r) { out.records.push_back(r); };
    hooks.on_checkpoint = [&](const Population& p, const EvolutionState& s, bool) {
        auto h = header_for(c);
        h.population = p;
        h.state = s;
        out.checkpoints.push_back(io::to_xml(h));
    };
    out.result = evolve(c, b, StopConditions{generations, 1e9}, ps, eval, st, std::move(start), hooks);
    return out;
}

TEST(Evolution, SameSeedGivesIdenticalPopulations) {
    const auto c = small_gp_config();
    const auto a = run(c, {}, 6, 42);
    const auto b = run(c, {}, 6, 42);
    ASSERT_EQ(a.checkpoints.size(), 6u);
    EXPECT_EQ(a.checkpoints, b.checkpoints);
    const auto other = run(c, {}, 6, 43);
    EXPECT_NE(a.checkpoints.back(), other.checkpoints.back());
}

TEST(Evolution, ResumeFromACheckpointIsExact) {
    for (auto variant : {BloatVariant::Simple, BloatVariant::Heavy, BloatVariant::VeryHeavy}) {
        const auto c = small_gp_config();
        const BloatConfig b{true, variant};
        const auto full = run(c, b, 8, 7);
        const auto part = run(c, b, 3, 7);
        // Through text, as a real resume goes through a file.
        auto saved = io::parse_population(part.checkpoints.back(), "gen-0002.xml");
        const auto resumed = run(c, b, 8, 7, saved);
        ASSERT_FALSE(resumed.checkpoints.empty());
        EXPECT_EQ(resumed.checkpoints.back(), full.checkpoints.back()) << "variant " << static_cast<int>(variant);
        EXPECT_EQ(resumed.result.state.evaluations, full.result.state.evaluations);
    }
}

TEST(Evolution, ElitismKeepsTheBest) {
    auto c = small_gp_config();
    c.elitism = 1;
    const auto r = run(c, {}, 10, 5);
    for (std::size_t i = 1; i < r.records.size(); ++i) EXPECT_GE(r.records[i].best, r.records[i - 1].best);
}

TEST(Evolution, StopsAtMinimumFitness) {
    const auto c = small_gp_config();
    tree::PrimitiveSet ps(c.primitives);
    QuadraticEvaluator eval;
    EvolutionState st;
    st.rng = Rng(3);
    const auto r = evolve(c, {}, StopConditions{100, -1e29}, ps, eval, st, std::nullopt, {});
    EXPECT_EQ(r.reason, StopReason::MinimumFitness);
    EXPECT_EQ(r.population.generation, 0);
}

TEST(Evolution, InterruptStopsAtAGenerationBoundary) {
    const auto c = small_gp_config();
    tree::PrimitiveSet ps(c.primitives);
    QuadraticEvaluator eval;
    std::atomic<bool> stop{false};
    EvolutionHooks hooks;
    int checkpoints = 0;
    bool last_seen = false;
    hooks.on_generation = [&](const GenerationRecord& r) {
        if (r.generation == 2) stop = true;
    };
    hooks.on_checkpoint = [&](const Population&, const EvolutionState&, bool last) {
        ++checkpoints;
        last_seen = last;
    };
    hooks.stop_requested = &stop;
    EvolutionState st;
    st.rng = Rng(3);
    const auto r = evolve(c, {}, StopConditions{50, 1e9}, ps, eval, st, std::nullopt, hooks);
    EXPECT_EQ(r.reason, StopReason::Interrupted);
    EXPECT_EQ(r.population.generation, 2);
    EXPECT_EQ(checkpoints, 3);
    EXPECT_TRUE(last_seen);
}

TEST(Evolution, PreventDuplicatesKeepsGenotypesUnique) {
    auto c = small_gp_config();
    c.prevent_duplicates = true;
    const auto r = run(c, {}, 5, 11);
    std::set<std::uint64_t> hashes;
    for (const auto& ind : r.result.population) hashes.insert(tree::hash(ind->genotype));
    EXPECT_EQ(hashes.size(), r.result.population.size());
}

TEST(Evolution, BadStopConditionThrows) {
    const auto c = small_gp_config();
    tree::PrimitiveSet ps(c.primitives);
    QuadraticEvaluator eval;
    const EvolutionState st;
    EXPECT_THROW(evolve(c, {}, StopConditions{0, 1}, ps, eval, st, std::nullopt, {}),
                 std::invalid_argument);
}

} // namespace
} // namespace cic::gp
