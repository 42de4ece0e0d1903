// Direct genes beside the trees (GpConfig::direct, Offset-HybrID): the
// operators' bad arguments, same seed same genes, their hash, and the GP loop
// carrying them: initialised, inherited, moved and resumed exactly. (Without
// them the loop draws what it drew before: the golden hashes check that.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "cic/gp/dedup.hpp"
#include "cic/gp/evolution.hpp"
#include "cic/gp/operators.hpp"
#include "support/gp_fixtures.hpp"

namespace cic::gp {
namespace {

using cic::testing::small_gp_config;

DirectGenes genes(std::size_t count, double sigma = 0.3, double rate = 0.5) {
    DirectGenes g;
    g.count = count;
    g.limit = 2.0;
    g.sigma = sigma;
    g.rate = rate;
    return g;
}

// Scores the trees (QuadraticEvaluator's way) minus how far the genes are from 1:
// fitness depends on the genes, so selection moves them.
class GeneEvaluator final : public Evaluator {
public:
    void evaluate(std::span<const IndividualPtr> todo) override {
        inner_.evaluate(todo);
        for (const auto& ind : todo)
            for (double g : ind->direct) ind->fitness -= std::abs(g - 1.0);
    }
private:
    cic::testing::QuadraticEvaluator inner_;
};

TEST(DirectGenes, BadArgumentsThrow) {
    Rng rng(1);
    EXPECT_THROW(initial_direct(rng, genes(3, -0.1)), std::invalid_argument);
    EXPECT_THROW(initial_direct(rng, genes(3, NAN)), std::invalid_argument);
    DirectGenes no_limit = genes(3);
    no_limit.limit = 0;
    EXPECT_THROW(initial_direct(rng, no_limit), std::invalid_argument);
    EXPECT_THROW(mutate_direct(rng, {0.0, 0.0, 0.0}, genes(3, 0.1, 1.5)), std::invalid_argument);
    EXPECT_THROW(mutate_direct(rng, {0.0, 0.0}, genes(3)), std::invalid_argument);
    EXPECT_THROW(mutate_direct(rng, {0.0, INFINITY, 0.0}, genes(3)), std::invalid_argument);
}

TEST(DirectGenes, SameSeedSameGenesWithinTheLimit) {
    Rng a(7), b(7);
    const auto ga = initial_direct(a, genes(12, 5.0));
    const auto gb = initial_direct(b, genes(12, 5.0));
    EXPECT_EQ(ga, gb);
    EXPECT_EQ(mutate_direct(a, ga, genes(12, 5.0, 1.0)), mutate_direct(b, gb, genes(12, 5.0, 1.0)));
    for (double g : ga) EXPECT_LE(std::abs(g), 2.0);   // sigma 5 reaches the clamp
    EXPECT_TRUE(std::any_of(ga.begin(), ga.end(), [](double g) { return std::abs(g) == 2.0; }));
    // Rate 0 moves nothing; count 0 draws nothing.
    Rng c(3);
    EXPECT_EQ(mutate_direct(c, ga, genes(12, 0.3, 0.0)), ga);
    Rng d(3), e(3);
    EXPECT_TRUE(initial_direct(d, genes(0)).empty());
    EXPECT_EQ(d.state(), e.state());
}

TEST(DirectGenes, HashCoversTheGenesAndKeepsTheTreesHashWithout) {
    const tree::Forest f{tree::Tree::parse("(add x0 1)")};
    EXPECT_EQ(genotype_hash(f), tree::hash(f));
    const std::vector<double> g1{0.5, -0.25}, g2{0.5, -0.2500000000000001};
    EXPECT_NE(genotype_hash(f, g1), tree::hash(f));
    EXPECT_NE(genotype_hash(f, g1), genotype_hash(f, g2));
    EXPECT_EQ(genotype_hash(f, g1), genotype_hash(f, std::vector<double>{0.5, -0.25}));
    SeenGenotypes seen;
    EXPECT_TRUE(seen.insert(f, g1));
    EXPECT_TRUE(seen.insert(f, g2));   // the same trees with other genes: another genotype
    EXPECT_FALSE(seen.insert(f, g1));
}

EvolutionResult run(const GpConfig& c, int generations, std::uint64_t seed) {
    const tree::PrimitiveSet ps(c.primitives);
    GeneEvaluator eval;
    EvolutionState st;
    st.seed = seed;
    st.rng = Rng(seed);
    return evolve(c, BloatConfig{}, StopConditions{generations, 1e9}, ps, eval, st, std::nullopt, {});
}

TEST(DirectGenes, TheLoopCarriesInheritsAndMovesThem) {
    GpConfig c = small_gp_config();
    c.direct = genes(4, 0.3, 0.5);
    c.elitism = 1;
    const auto a = run(c, 8, 11), b = run(c, 8, 11);
    ASSERT_EQ(a.population.size(), b.population.size());
    std::set<std::vector<double>> distinct;
    for (std::size_t i = 0; i < a.population.size(); ++i) {
        EXPECT_EQ(a.population[i].direct, b.population[i].direct);   // same seed, same genes
        EXPECT_EQ(a.population[i].fitness, b.population[i].fitness);
        ASSERT_EQ(a.population[i].direct.size(), 4u);
        for (double g : a.population[i].direct) EXPECT_LE(std::abs(g), 2.0);
        distinct.insert(a.population[i].direct);
    }
    EXPECT_GT(distinct.size(), 1u);
    // Selection pulled the genes towards 1 from N(0, 0.3): the best's mean gene rose.
    double mean = 0;
    for (double g : a.population.best().direct) mean += g / 4;
    EXPECT_GT(mean, 0.2);
}

TEST(DirectGenes, ResumingInMemoryIsExact) {
    GpConfig c = small_gp_config();
    c.direct = genes(3);
    const auto full = run(c, 7, 4);
    auto half = run(c, 4, 4);
    const tree::PrimitiveSet ps(c.primitives);
    GeneEvaluator eval;
    const auto rest = evolve(c, BloatConfig{}, StopConditions{7, 1e9}, ps, eval, half.state,
                             std::move(half.population), {});
    ASSERT_EQ(rest.population.size(), full.population.size());
    for (std::size_t i = 0; i < full.population.size(); ++i) {
        EXPECT_EQ(rest.population[i].direct, full.population[i].direct);
        EXPECT_EQ(rest.population[i].genotype, full.population[i].genotype);
    }
    EXPECT_EQ(rest.state.rng.state(), full.state.rng.state());
}

} // namespace
} // namespace cic::gp
