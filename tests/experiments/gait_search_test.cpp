// gait::Encoding and gait::Search (pagmo2): bad arguments throw, the same seed
// gives the same search, a saved state continues bit for bit, and the batch
// evaluation sees every point the optimiser evaluates.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <stdexcept>

#include "cic/experiments/gait/encoding.hpp"
#include "cic/experiments/gait/search.hpp"

namespace cic::gait {
namespace {

// A smooth test landscape with its maximum 0 at x = 0.3 everywhere.
double sphere(const std::vector<double>& x) {
    double s = 0;
    for (double v : x) s -= (v - 0.3) * (v - 0.3);
    return s;
}

struct CountingEvaluator {
    long calls = 0, points = 0;
    std::vector<double> operator()(const std::vector<std::vector<double>>& xs) {
        ++calls;
        points += static_cast<long>(xs.size());
        std::vector<double> f;
        for (const auto& x : xs) f.push_back(sphere(x));
        return f;
    }
};

std::uint64_t bits(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

TEST(GaitEncoding, DecodesTheUnitBoxIntoServoRanges) {
    const Encoding e(2, true, 0.5, 2.5);
    EXPECT_EQ(e.dimension(), 11u);
    std::vector<double> x(11, 0.5);
    x[0] = 1.0;
    x[1] = 2.0;    // amplitude clamped to the servo's half range
    x[2] = 1.25;   // phase wraps
    x[3] = -1.0;   // offset clamped to -pi/2
    const sim::GaitSpec g = e.decode(x);
    EXPECT_DOUBLE_EQ(g.frequency, 2.5);
    ASSERT_EQ(g.joints.size(), 2u);
    EXPECT_DOUBLE_EQ(g.joints[0].amplitude, std::numbers::pi / 2);
    EXPECT_NEAR(g.joints[0].phase, std::numbers::pi / 2, 1e-12);
    EXPECT_DOUBLE_EQ(g.joints[0].offset, -std::numbers::pi / 2);
    EXPECT_DOUBLE_EQ(g.joints[1].offset, 0.0);
    EXPECT_DOUBLE_EQ(g.joints[1].amplitude2, std::numbers::pi / 4);
    EXPECT_EQ(Encoding(3, false, 0.1, 3).dimension(), 10u);
    EXPECT_EQ(default_population(10, 5), 10);   // 4 + floor(3 ln 10)
    EXPECT_EQ(default_population(1, 7), 7);
}

// Reflect mirrors a value at the bounds (continuous, no flat region outside
// the box); clamp holds it at the bound. Phases wrap under both.
TEST(GaitEncoding, ReflectMirrorsAtTheBoundsWhereClampHolds) {
    const Encoding clamp(1, false, 1.0, 3.0, Bounds::Clamp), reflect(1, false, 1.0, 3.0, Bounds::Reflect);
    constexpr double pi = std::numbers::pi;
    const std::vector<double> x{1.25, -0.3, 1.25, 2.6};   // frequency, amplitude, phase, offset
    const sim::GaitSpec c = clamp.decode(x), r = reflect.decode(x);
    EXPECT_DOUBLE_EQ(c.frequency, 3.0);
    EXPECT_DOUBLE_EQ(r.frequency, 1.0 + 0.75 * 2.0);
    EXPECT_DOUBLE_EQ(c.joints[0].amplitude, 0.0);
    EXPECT_NEAR(r.joints[0].amplitude, 0.3 * pi / 2, 1e-12);
    EXPECT_NEAR(c.joints[0].phase, r.joints[0].phase, 1e-12);
    EXPECT_NEAR(r.joints[0].phase, pi / 2, 1e-12);
    EXPECT_DOUBLE_EQ(c.joints[0].offset, pi / 2);
    EXPECT_NEAR(r.joints[0].offset, (2.0 * 0.6 - 1.0) * pi / 2, 1e-12);   // 2.6 -> 0.6 (period 2)
    // Inside the box the two agree; across a bound reflect is continuous.
    const std::vector<double> inside{0.3, 0.7, 0.2, 0.9};
    EXPECT_EQ(clamp.decode(inside).joints[0].offset, reflect.decode(inside).joints[0].offset);
    EXPECT_NEAR(reflect.decode(std::vector<double>{1.0 + 1e-9, 0.5, 0.5, 0.5}).frequency, 3.0, 1e-8);
}

TEST(GaitEncoding, BadArgumentsThrow) {
    EXPECT_THROW(Encoding(0, false, 0.1, 1), std::invalid_argument);
    EXPECT_THROW(Encoding(1, false, 0, 1), std::invalid_argument);
    EXPECT_THROW(Encoding(1, false, 2, 1), std::invalid_argument);
    const Encoding e(1, false, 0.1, 1);
    EXPECT_THROW(e.decode(std::vector<double>(3)), std::invalid_argument);
    EXPECT_THROW(e.decode(std::vector<double>{0.5, std::nan(""), 0.5, 0.5}), std::invalid_argument);
}

TEST(GaitSearch, BadArgumentsThrow) {
    EXPECT_THROW(Search(Optimizer::Cmaes, 0, 10, 0.3, 1), std::invalid_argument);
    EXPECT_THROW(Search(Optimizer::Cmaes, 4, 4, 0.3, 1), std::invalid_argument);
    EXPECT_THROW(Search(Optimizer::Sade, 4, 6, 0.3, 1), std::invalid_argument);
    EXPECT_THROW(Search(Optimizer::Xnes, 4, 8, 0.0, 1), std::invalid_argument);
    Search s(Optimizer::Cmaes, 4, 8, 0.3, 1);
    CountingEvaluator eval;
    EXPECT_THROW(s.step(std::ref(eval)), std::logic_error);
    s.initialise(std::ref(eval));
    s.step(std::ref(eval));
    std::vector<double> history = s.history();
    ASSERT_EQ(history.size(), 16u);
    Search other(Optimizer::Cmaes, 4, 8, 0.3, 1);
    EXPECT_THROW(other.replay(history, 2), std::invalid_argument);   // too short
    EXPECT_THROW(other.replay(history, 0), std::invalid_argument);   // too long
    EXPECT_THROW(other.replay(history, -1), std::invalid_argument);
}

class EveryOptimizer : public ::testing::TestWithParam<Optimizer> {};

// Each generation's points are evaluated in one batch, the optimiser improves
// on a smooth landscape, and the same seed repeats the search exactly.
TEST_P(EveryOptimizer, BatchesEveryGenerationAndRepeatsWithTheSeed) {
    auto run = [](std::uint64_t seed, CountingEvaluator& eval) {
        Search s(GetParam(), 6, 10, 0.3, seed);
        s.initialise(std::ref(eval));
        for (int g = 0; g < 30; ++g) s.step(std::ref(eval));
        return s.champion();
    };
    CountingEvaluator a, b, c;
    const Candidate ca = run(7, a), cb = run(7, b), cc = run(8, c);
    EXPECT_EQ(a.calls, 31);                 // one batch per generation
    EXPECT_EQ(a.points, 31 * 10);
    EXPECT_EQ(bits(ca.fitness), bits(cb.fitness));
    EXPECT_EQ(ca.x, cb.x);
    EXPECT_NE(ca.x, cc.x);
    EXPECT_GT(ca.fitness, -0.05) << "the optimiser should approach the maximum 0";
}

// Replaying the history of generation 10 in a fresh Search (a resume) and
// continuing gives the same generations 11..20 as an uninterrupted search.
TEST_P(EveryOptimizer, SavedStateContinuesBitForBit) {
    CountingEvaluator eval;
    Search whole(GetParam(), 5, 9, 0.3, 3);
    whole.initialise(std::ref(eval));
    for (int g = 0; g < 10; ++g) whole.step(std::ref(eval));
    const std::vector<double> history = whole.history();
    const auto population = whole.population();
    for (int g = 0; g < 10; ++g) whole.step(std::ref(eval));

    Search resumed(GetParam(), 5, 9, 0.3, 3);
    CountingEvaluator none;
    resumed.replay(history, 10);
    EXPECT_EQ(none.calls, 0);
    ASSERT_EQ(resumed.population().size(), population.size());
    for (std::size_t i = 0; i < population.size(); ++i) EXPECT_EQ(resumed.population()[i].x, population[i].x);
    for (int g = 0; g < 10; ++g) resumed.step(std::ref(eval));
    ASSERT_EQ(resumed.population().size(), whole.population().size());
    for (std::size_t i = 0; i < whole.population().size(); ++i) {
        EXPECT_EQ(resumed.population()[i].x, whole.population()[i].x) << i;
        EXPECT_EQ(bits(resumed.population()[i].fitness), bits(whole.population()[i].fitness)) << i;
    }
    EXPECT_EQ(resumed.champion().x, whole.champion().x);
    EXPECT_EQ(resumed.evaluations(), whole.evaluations());
    EXPECT_EQ(resumed.history(), whole.history());
    EXPECT_EQ(resumed.generation(), 20);
}

INSTANTIATE_TEST_SUITE_P(Gait, EveryOptimizer, ::testing::Values(Optimizer::Cmaes, Optimizer::Xnes, Optimizer::Sade),
                         [](const auto& info) { return to_string(info.param); });

} // namespace
} // namespace cic::gait
