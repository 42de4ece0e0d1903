#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "cic/gp/operators.hpp"

using namespace cic;
using namespace cic::gp;
using namespace cic::tree;

namespace {

IndividualPtr make(std::uint64_t id, double fitness, const std::string& tree = "x0") {
    auto p = std::make_shared<Individual>();
    p->id = id;
    p->fitness = fitness;
    p->evaluated = true;
    p->genotype = {Tree::parse(tree)};
    return p;
}

std::vector<int> counts(const std::function<std::size_t(Rng&)>& pick, std::size_t n, int draws, std::uint64_t seed) {
    Rng rng(seed);
    std::vector<int> c(n);
    for (int i = 0; i < draws; ++i) ++c[pick(rng)];
    return c;
}

} // namespace

TEST(Tournament, LexicographicParsimonyPrefersTheSmallerOnEqualFitness) {
    const std::vector<IndividualPtr> pop{make(1, 5.0, "(add x0 (mul x0 x0))"), make(2, 5.0, "x0")};
    auto c = counts([&](Rng& r) { return tournament(r, pop, 20, true); }, 2, 500, 1);
    EXPECT_EQ(c[1], 500);   // 20 draws: both met with near certainty, the small one always wins
    c = counts([&](Rng& r) { return tournament(r, pop, 20, false); }, 2, 500, 1);
    EXPECT_GT(c[0], 150);   // without parsimony the first drawn keeps the tie
    EXPECT_GT(c[1], 150);
    // Parsimony never overrides fitness.
    const std::vector<IndividualPtr> pop2{make(1, 6.0, "(add x0 (mul x0 x0))"), make(2, 5.0, "x0")};
    c = counts([&](Rng& r) { return tournament(r, pop2, 20, true); }, 2, 500, 1);
    EXPECT_EQ(c[0], 500);
}

TEST(Tournament, SizeSetsPressure) {
    std::vector<IndividualPtr> pop;
    for (int i = 0; i < 10; ++i) pop.push_back(make(static_cast<std::uint64_t>(i), i));
    const auto uniform = counts([&](Rng& r) { return tournament(r, pop, 1, true); }, 10, 10000, 2);
    for (int c : uniform) EXPECT_NEAR(c, 1000, 150);
    const auto strong = counts([&](Rng& r) { return tournament(r, pop, 5, true); }, 10, 10000, 2);
    EXPECT_NEAR(strong[9] / 10000.0, 1.0 - std::pow(0.9, 5), 0.02);   // best is in the tournament
}

TEST(Tournament, SameSeedSameWinnersAndBadArgumentsThrow) {
    std::vector<IndividualPtr> pop;
    for (int i = 0; i < 10; ++i) pop.push_back(make(static_cast<std::uint64_t>(i), i % 3));
    EXPECT_EQ(counts([&](Rng& r) { return tournament(r, pop, 3, true); }, 10, 100, 4),
              counts([&](Rng& r) { return tournament(r, pop, 3, true); }, 10, 100, 4));
    Rng rng(1);
    EXPECT_THROW(tournament(rng, std::vector<IndividualPtr>{}, 3, true), std::invalid_argument);
    EXPECT_THROW(tournament(rng, pop, 0, true), std::invalid_argument);
    const std::vector<IndividualPtr> with_null{nullptr};
    EXPECT_THROW(tournament(rng, with_null, 1, true), std::invalid_argument);
}

TEST(Roulette, ProportionalToFitness) {
    const std::vector<IndividualPtr> pop{make(1, 1.0), make(2, 2.0), make(3, 7.0)};
    const auto c = counts([&](Rng& r) { return roulette(r, pop); }, 3, 20000, 5);
    EXPECT_NEAR(c[0] / 20000.0, 0.1, 0.01);
    EXPECT_NEAR(c[1] / 20000.0, 0.2, 0.01);
    EXPECT_NEAR(c[2] / 20000.0, 0.7, 0.01);
}

TEST(Roulette, NegativeFitnessIsShifted) {
    // Shift by (1e-12 - min): weights 1e-12, 2, 4 -> the worst is (almost) never picked.
    const std::vector<IndividualPtr> pop{make(1, -6.0), make(2, -4.0), make(3, -2.0)};
    const auto c = counts([&](Rng& r) { return roulette(r, pop); }, 3, 12000, 6);
    EXPECT_EQ(c[0], 0);
    EXPECT_NEAR(c[1] / 12000.0, 1.0 / 3.0, 0.015);
    EXPECT_NEAR(c[2] / 12000.0, 2.0 / 3.0, 0.015);
    // All equal (and negative): every weight is 1e-12, so uniform.
    const std::vector<IndividualPtr> flat{make(1, -3.0), make(2, -3.0)};
    const auto f = counts([&](Rng& r) { return roulette(r, flat); }, 2, 4000, 6);
    EXPECT_NEAR(f[0] / 4000.0, 0.5, 0.03);
}

TEST(Roulette, SameSeedSameResultAndBadArgumentsThrow) {
    const std::vector<IndividualPtr> pop{make(1, 1.0), make(2, 2.0), make(3, 7.0)};
    EXPECT_EQ(counts([&](Rng& r) { return roulette(r, pop); }, 3, 100, 7),
              counts([&](Rng& r) { return roulette(r, pop); }, 3, 100, 7));
    Rng rng(1);
    EXPECT_THROW(roulette(rng, std::vector<IndividualPtr>{}), std::invalid_argument);
    const std::vector<IndividualPtr> bad{make(1, 1.0), make(2, std::numeric_limits<double>::quiet_NaN())};
    EXPECT_THROW(roulette(rng, bad), std::invalid_argument);
    const std::vector<IndividualPtr> inf{make(1, -std::numeric_limits<double>::infinity())};
    EXPECT_THROW(roulette(rng, inf), std::invalid_argument);
}

TEST(Select, DispatchesOnTheConfiguredType) {
    std::vector<IndividualPtr> pop;
    for (int i = 0; i < 10; ++i) pop.push_back(make(static_cast<std::uint64_t>(i), i + 1));
    GpConfig cfg;
    cfg.selection = SelectionType::Tournament;
    cfg.tournament_size = 4;
    Rng a(9), b(9);
    for (int i = 0; i < 50; ++i) ASSERT_EQ(select(a, pop, cfg), tournament(b, pop, 4, true));
    cfg.selection = SelectionType::Roulette;
    for (int i = 0; i < 50; ++i) ASSERT_EQ(select(a, pop, cfg), roulette(b, pop));
    cfg.selection = static_cast<SelectionType>(7);
    EXPECT_THROW(select(a, pop, cfg), std::invalid_argument);
}
