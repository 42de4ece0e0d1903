// The stages of the generational loop one by one (Initialise, Breed,
// BloatControl with each variant and the depth cap), then evolve() itself:
// bad arguments, same seed, in-memory resume, stop rules.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "cic/gp/evolution.hpp"
#include "cic/tree/eval.hpp"
#include "support/gp_fixtures.hpp"

namespace cic::gp {
namespace {

using cic::testing::QuadraticEvaluator;
using cic::testing::small_gp_config;

// Forgets to evaluate: the loop must notice.
class LazyEvaluator final : public Evaluator {
public:
    void evaluate(std::span<const IndividualPtr>) override {}
};

EvolutionState state(std::uint64_t seed) {
    EvolutionState st;
    st.seed = seed;
    st.rng = Rng(seed);
    return st;
}

// A tree of exactly `depth` levels: (neg (neg ... x0)).
tree::Tree chain(int depth) {
    std::string text = "x0";
    for (int i = 1; i < depth; ++i) text = "(neg " + text + ")";
    return tree::Tree::parse(text);
}

IndividualPtr individual(std::uint64_t id, double fitness, int depth, std::vector<std::uint64_t> parents = {}) {
    auto p = std::make_shared<Individual>();
    p->id = id;
    p->fitness = fitness;
    p->evaluated = true;
    p->genotype = {chain(depth)};
    p->parents = std::move(parents);
    return p;
}

// Every node is a function of the set, a variable it has, or one of its constants.
::testing::AssertionResult in_primitive_set(const tree::Forest& f, const tree::PrimitiveSet& ps) {
    const auto& cfg = ps.config();
    for (const auto& t : f)
        for (const auto& n : t.nodes()) {
            if (n.op == tree::Op::Var) {
                if (n.var >= ps.variable_count()) return ::testing::AssertionFailure() << "x" << n.var;
            } else if (n.op == tree::Op::Const) {
                const bool listed = std::find(cfg.constants.begin(), cfg.constants.end(), n.value) != cfg.constants.end();
                const bool ephemeral = cfg.ephemeral && n.value >= cfg.ephemeral_min && n.value < cfg.ephemeral_max;
                if (!listed && !ephemeral) return ::testing::AssertionFailure() << "constant " << n.value;
            } else if (!ps.allows(n.op)) {
                return ::testing::AssertionFailure() << "function " << tree::name(n.op);
            }
        }
    return ::testing::AssertionSuccess();
}

std::vector<std::string> texts(const Population& pop) {
    std::vector<std::string> out;
    for (const auto& ind : pop) {
        std::string line;
        for (const auto& t : ind->genotype) line += t.to_string() + " ";
        out.push_back(line + std::to_string(ind->fitness));
    }
    return out;
}

// ------------------------------------------------------------------ Initialise

TEST(Initialise, UniqueGenotypesFromThePrimitiveSetWithinTheDepth) {
    GpConfig c = small_gp_config();
    c.trees_per_genotype = 2;
    c.primitives.ephemeral = true;
    const tree::PrimitiveSet ps(c.primitives);
    Initialise init(c, ps);
    EvolutionState st = state(7);
    Population pop;
    init.apply(pop, st);
    ASSERT_EQ(pop.size(), 30u);
    EXPECT_EQ(pop.generation, 0);
    SeenGenotypes seen;
    for (const auto& ind : pop) {
        EXPECT_TRUE(seen.insert(ind->genotype));
        EXPECT_EQ(ind->genotype.size(), 2u);
        EXPECT_TRUE(in_primitive_set(ind->genotype, ps));
        for (const auto& t : ind->genotype) EXPECT_LE(t.depth(), c.generated_tree_levels());
        EXPECT_FALSE(ind->evaluated);
        EXPECT_TRUE(ind->parents.empty());
    }
    EXPECT_EQ(st.next_id, 31u);
    // Same seed, same population.
    EvolutionState again = state(7);
    Population twin;
    init.apply(twin, again);
    EXPECT_EQ(texts(pop), texts(twin));
}

// ----------------------------------------------------------------------- Breed

struct Bred {
    Population parents, children;
};

Bred breed_once(const GpConfig& c, std::uint64_t seed) {
    const tree::PrimitiveSet ps(c.primitives);
    QuadraticEvaluator eval;
    Initialise init(c, ps);
    Evaluate evaluate(eval);
    Breed breed(c, ps);
    EvolutionState st = state(seed);
    Bred out;
    init.apply(out.parents, st);
    evaluate.apply(out.parents, st);
    out.children = out.parents;
    breed.apply(out.children, st);
    return out;
}

TEST(Breed, ChildrenFillThePopulationFromTheSetWithKnownParents) {
    const GpConfig c = small_gp_config();
    const tree::PrimitiveSet ps(c.primitives);
    const Bred b = breed_once(c, 3);
    ASSERT_EQ(b.children.size(), b.parents.size());
    EXPECT_EQ(b.children.generation, 1);
    std::set<std::uint64_t> parent_ids;
    for (const auto& p : b.parents) parent_ids.insert(p->id);
    SeenGenotypes seen;
    for (const auto& child : b.children) {
        EXPECT_GT(child->id, *parent_ids.rbegin());   // new ids, handed out in order
        ASSERT_FALSE(child->parents.empty());
        EXPECT_LE(child->parents.size(), 2u);
        for (auto id : child->parents) EXPECT_TRUE(parent_ids.count(id)) << id;
        EXPECT_TRUE(in_primitive_set(child->genotype, ps));
        EXPECT_TRUE(seen.insert(child->genotype)) << "preventDuplicates";
    }
    EXPECT_EQ(texts(b.children), texts(breed_once(c, 3).children));
    EXPECT_NE(texts(b.children), texts(breed_once(c, 4).children));
}

TEST(Breed, ReproductionCopiesAParentWithItsFitness) {
    GpConfig c = small_gp_config();
    c.crossover_rate = 0;
    c.mutation_rate = 0;
    c.prevent_duplicates = false;
    const Bred b = breed_once(c, 5);
    for (const auto& child : b.children) {
        ASSERT_EQ(child->parents.size(), 1u);
        const auto parent = std::find_if(b.parents.begin(), b.parents.end(),
                                         [&](const IndividualPtr& p) { return p->id == child->parents[0]; });
        ASSERT_NE(parent, b.parents.end());
        EXPECT_EQ(child->genotype, (*parent)->genotype);
        EXPECT_TRUE(child->evaluated);   // a copy is not evaluated again
        EXPECT_EQ(child->fitness, (*parent)->fitness);
    }
}

TEST(Breed, ElitesSurviveUnchanged) {
    GpConfig c = small_gp_config();
    c.elitism = 3;
    const Bred b = breed_once(c, 9);
    std::vector<const Individual*> ranked;
    for (const auto& p : b.parents) ranked.push_back(p.get());
    std::sort(ranked.begin(), ranked.end(), [](auto* x, auto* y) { return better(*x, *y); });
    for (int e = 0; e < 3; ++e) EXPECT_EQ(b.children.individuals[e].get(), ranked[e]) << "elite " << e;
}

TEST(Breed, MutationOnlyChildrenStayInTheSet) {
    GpConfig c = small_gp_config();
    c.crossover_rate = 0;
    c.mutation_rate = 1;
    c.primitives.ephemeral = true;
    const tree::PrimitiveSet ps(c.primitives);
    const Bred b = breed_once(c, 11);
    for (const auto& child : b.children) {
        EXPECT_EQ(child->parents.size(), 1u);
        EXPECT_TRUE(in_primitive_set(child->genotype, ps));
    }
}

// ---------------------------------------------------------------- BloatControl

// Parents: ids 1..3 with depths 4, 2, 3; the best (id 1, fitness 5) is 4 deep.
// The breeder is run on them once so that BloatControl can look them up.
struct BloatBench {
    GpConfig gp = small_gp_config();
    BloatConfig bloat;
    tree::PrimitiveSet ps{small_gp_config().primitives};
    Population parents;
    EvolutionState st = state(1);

    explicit BloatBench(BloatVariant variant, bool enabled = true) {
        gp.population_size = 3;
        gp.tournament_size = 2;
        gp.max_init_depth = 4;
        bloat.variant = variant;
        bloat.enabled = enabled;
        parents.individuals = {individual(1, 5.0, 4), individual(2, 1.0, 2), individual(3, 2.0, 3)};
        st.next_id = 100;
    }
    // Filters `children` (given parent ids) after breeding from the parents.
    Population filter(Population children) {
        Breed breed(gp, ps);
        BloatControl control(gp, bloat, breed);
        control.initialise(parents, st);
        Population scratch = parents;
        breed.apply(scratch, st);   // only to make `parents` the bred-from generation
        std::vector<std::size_t> all(children.size());
        for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
        control.filter(children, st, all);
        control.end_generation(children, st);
        return children;
    }
};

TEST(BloatControl, SimpleReplacesADeeperChildThatIsNotBetterByItsFirstParent) {
    BloatBench bench(BloatVariant::Simple);
    Population children;
    children.individuals = {individual(10, 4.0, 6, {2, 1}),    // deeper than 4, not better: replaced
                            individual(11, 9.0, 6, {2, 3}),    // deeper and better: kept, limit 6
                            individual(12, -3.0, 3, {3})};     // within the limit: kept
    const Population out = bench.filter(children);
    EXPECT_EQ(out[0].genotype, bench.parents[1].genotype);   // a copy of parent 2
    EXPECT_EQ(out[0].fitness, 1.0);
    EXPECT_EQ(out[0].parents, std::vector<std::uint64_t>{2});
    EXPECT_GE(out[0].id, 100u);
    EXPECT_EQ(out[1].id, 11u);
    EXPECT_EQ(out[2].id, 12u);
    EXPECT_EQ(bench.st.bloat.limit, 6);
    for (const auto& ind : out) EXPECT_FALSE(ind->illegal);   // Simple marks nobody
}

TEST(BloatControl, HeavyLowersTheLimitNoFurtherThanTheInitialMaximum) {
    BloatBench bench(BloatVariant::Heavy);
    Population children;
    children.individuals = {individual(10, 9.0, 7, {1, 2}),   // better: kept, limit 7
                            individual(11, 1.0, 4, {1}), individual(12, 1.5, 6, {2, 3})};
    Population out = bench.filter(children);
    // End of generation: the best (depth 7) keeps the limit at 7; nobody over it.
    EXPECT_EQ(bench.st.bloat.limit, 7);
    // A shallower best next time lowers it, but not below the initial maximum
    // (PTC1 to depth 4: 5 levels); the 6-deep individual is then illegal.
    const int initial = bench.gp.generated_forest_depth();
    ASSERT_EQ(initial, 5);
    out.individuals[0] = individual(13, 20.0, 2, {1});
    const Breed breed(bench.gp, bench.ps);
    BloatControl control(bench.gp, bench.bloat, breed);
    control.end_generation(out, bench.st);
    EXPECT_EQ(bench.st.bloat.limit, initial);
    EXPECT_FALSE(out[0].illegal);
    EXPECT_FALSE(out[1].illegal);
    EXPECT_TRUE(out[2].illegal);
}

TEST(BloatControl, VeryHeavyLowersTheLimitToTheBestsDepth) {
    BloatBench bench(BloatVariant::VeryHeavy);
    Population children;
    children.individuals = {individual(10, 9.0, 2, {1, 2}), individual(11, 1.0, 3, {2}),
                            individual(12, 1.5, 4, {3})};
    const Population out = bench.filter(children);
    EXPECT_EQ(bench.st.bloat.limit, 2);   // the best is 2 deep
    EXPECT_FALSE(out[0].illegal);
    EXPECT_TRUE(out[1].illegal);
    EXPECT_TRUE(out[2].illegal);
}

TEST(BloatControl, WithoutDynamicLimitsTheDepthCapApplies) {
    BloatBench bench(BloatVariant::Simple, false);
    bench.gp.max_tree_depth = 5;
    Population children;
    children.individuals = {individual(10, 99.0, 6, {2, 1}),   // over the cap, however good: replaced
                            individual(11, 0.0, 5, {3})};      // at the cap: kept
    const Population out = bench.filter(children);
    EXPECT_EQ(out[0].genotype, bench.parents[1].genotype);
    EXPECT_EQ(out[1].id, 11u);
    bench.gp.max_tree_depth = 0;   // 0 = no cap
    EXPECT_EQ(bench.filter(children)[0].id, 10u);
}

// ---------------------------------------------------------------------- evolve

EvolutionResult run(const GpConfig& c, int generations, std::uint64_t seed, std::vector<GenerationRecord>* records = nullptr,
                    const std::atomic<bool>* stop = nullptr, double minimum_fitness = 1e9) {
    const tree::PrimitiveSet ps(c.primitives);
    QuadraticEvaluator eval;
    EvolutionHooks hooks;
    if (records) hooks.on_generation = [records](const GenerationRecord& r) { records->push_back(r); };
    hooks.stop_requested = stop;
    return evolve(c, BloatConfig{}, StopConditions{generations, minimum_fitness}, ps, eval, state(seed), std::nullopt,
                  hooks);
}

TEST(Evolve, BadArgumentsThrow) {
    const GpConfig c = small_gp_config();
    const tree::PrimitiveSet ps(c.primitives);
    QuadraticEvaluator eval;
    EXPECT_THROW(evolve(c, BloatConfig{}, StopConditions{0, 1e9}, ps, eval, state(1), std::nullopt, {}),
                 std::invalid_argument);
    LazyEvaluator lazy;
    EXPECT_THROW(evolve(c, BloatConfig{}, StopConditions{3, 1e9}, ps, lazy, state(1), std::nullopt, {}),
                 std::logic_error);
}

TEST(Evolve, SameSeedSameRunAndOneRecordPerGeneration) {
    std::vector<GenerationRecord> records;
    const auto a = run(small_gp_config(), 6, 21, &records);
    const auto b = run(small_gp_config(), 6, 21);
    EXPECT_EQ(texts(a.population), texts(b.population));
    EXPECT_EQ(a.state.rng.state(), b.state.rng.state());
    EXPECT_NE(texts(a.population), texts(run(small_gp_config(), 6, 22).population));
    ASSERT_EQ(records.size(), 6u);
    for (int g = 0; g < 6; ++g) EXPECT_EQ(records[g].generation, g);
    EXPECT_EQ(a.reason, StopReason::MaximumIterations);
    EXPECT_EQ(a.population.generation, 5);
}

TEST(Evolve, ContinuingFromAGenerationGivesTheSameRun) {
    const GpConfig c = small_gp_config();
    const auto whole = run(c, 7, 4);
    const auto half = run(c, 3, 4);
    // A deep copy, as a population file would give.
    Population start;
    start.generation = half.population.generation;
    for (const auto& ind : half.population) start.individuals.push_back(std::make_shared<Individual>(*ind));
    const tree::PrimitiveSet ps(c.primitives);
    QuadraticEvaluator eval;
    const auto rest = evolve(c, BloatConfig{}, StopConditions{7, 1e9}, ps, eval, half.state, std::move(start), {});
    EXPECT_EQ(eval.calls, whole.state.evaluations - half.state.evaluations);
    EXPECT_EQ(texts(rest.population), texts(whole.population));
    EXPECT_EQ(rest.state.rng.state(), whole.state.rng.state());
    EXPECT_EQ(rest.state.bloat.limit, whole.state.bloat.limit);
}

// Generations, the loop a caller drives one generation at a time (the run's
// one loop, search/generational.cpp): stepped by hand it is evolve(), with
// bloat control on; a resumed one records the generation it was given.
TEST(Generations, SteppedByHandIsEvolve) {
    GpConfig c = small_gp_config();
    BloatConfig bloat;
    bloat.enabled = true;
    const tree::PrimitiveSet ps(c.primitives);
    QuadraticEvaluator a_eval, b_eval;
    const auto whole = evolve(c, bloat, StopConditions{5, 1e9}, ps, a_eval, state(8), std::nullopt, {});
    Generations g(c, bloat, ps, b_eval, state(8), std::nullopt);
    EXPECT_EQ(g.record(5).generation, 0);
    for (int i = 1; i < 5; ++i) {
        g.step();
        const GenerationRecord r = g.record(5);
        EXPECT_EQ(r.generation, i);
        EXPECT_EQ(r.max_generations, 5);
        EXPECT_EQ(r.evaluations, g.state().evaluations);
    }
    const EvolutionResult stepped = g.finish(StopReason::MaximumIterations);
    EXPECT_EQ(texts(stepped.population), texts(whole.population));
    EXPECT_EQ(stepped.state.rng.state(), whole.state.rng.state());
    EXPECT_EQ(stepped.state.bloat.limit, whole.state.bloat.limit);
    EXPECT_EQ(b_eval.calls, a_eval.calls);
    // From a saved generation: nothing evaluated again, and its record is that generation's.
    Population start;
    start.generation = stepped.population.generation;
    for (const auto& ind : stepped.population) start.individuals.push_back(std::make_shared<Individual>(*ind));
    QuadraticEvaluator c_eval;
    Generations resumed(c, bloat, ps, c_eval, stepped.state, std::move(start));
    EXPECT_EQ(c_eval.calls, 0);
    const GenerationRecord r = resumed.record(5);
    EXPECT_EQ(r.generation, 4);
    EXPECT_EQ(r.best, whole.population.best().fitness);
}

TEST(Evolve, StopsAtTheMinimumFitnessOrWhenAsked) {
    const auto reached = run(small_gp_config(), 50, 8, nullptr, nullptr, -1e9);
    EXPECT_EQ(reached.reason, StopReason::MinimumFitness);
    EXPECT_EQ(reached.population.generation, 0);
    const std::atomic<bool> stop{true};
    const auto asked = run(small_gp_config(), 50, 8, nullptr, &stop);
    EXPECT_EQ(asked.reason, StopReason::Interrupted);
    EXPECT_EQ(asked.population.generation, 0);
}

} // namespace
} // namespace cic::gp
