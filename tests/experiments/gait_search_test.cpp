// gait::Encoding and gait::Search (pagmo2): bad arguments throw, the same seed
// gives the same search, a saved state continues bit for bit, and the batch
// evaluation sees every point the optimiser evaluates; IPOP restarts happen on
// a stagnating function, double the population and replay exactly.
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

// A raw optimiser point and its unit-box form decode to the same gait, bit for
// bit, under both bounds rules and with the second harmonic (Python's read_run
// hands out the box form; evaluating it must give the stored fitness).
TEST(GaitEncoding, InBoxDecodesToTheSameBits) {
    for (Bounds b : {Bounds::Clamp, Bounds::Reflect}) {
        const Encoding e(2, true, 0.1, 3.0, b);
        const std::vector<double> x{1.239, -0.35, 7.25, 2.6, -1e-17, 1.0, 0.5, -3.75, 0.999999, 4.0, -0.0};
        const std::vector<double> box = e.in_box(x);
        for (double v : box) EXPECT_TRUE(v >= 0.0 && v <= 1.0) << v;
        const sim::GaitSpec a = e.decode(x), c = e.decode(box);
        EXPECT_EQ(bits(a.frequency), bits(c.frequency));
        for (std::size_t j = 0; j < 2; ++j) {
            EXPECT_EQ(bits(a.joints[j].amplitude), bits(c.joints[j].amplitude));
            EXPECT_EQ(bits(a.joints[j].phase), bits(c.joints[j].phase));
            EXPECT_EQ(bits(a.joints[j].offset), bits(c.joints[j].offset));
            EXPECT_EQ(bits(a.joints[j].amplitude2), bits(c.joints[j].amplitude2));
            EXPECT_EQ(bits(a.joints[j].phase2), bits(c.joints[j].phase2));
        }
        EXPECT_EQ(e.in_box(box), box);   // a point of the box is its own box form
    }
    EXPECT_THROW(Encoding(1, false, 0.1, 1).in_box(std::vector<double>(2)), std::invalid_argument);
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

// IPOP restarts (RestartRule). A landscape of plateaus (steps of 0.05 on the
// sphere): a start's best soon stops rising, so restarts do happen.
double plateaus(const std::vector<double>& x) { return std::floor(sphere(x) / 0.05) * 0.05; }

struct RecordingEvaluator {
    std::vector<std::size_t> batches;                      // size of each batch, in order
    std::vector<std::vector<std::vector<double>>> points;  // the points of each batch
    double (*f)(const std::vector<double>&) = plateaus;
    std::vector<double> operator()(const std::vector<std::vector<double>>& xs) {
        batches.push_back(xs.size());
        points.push_back(xs);
        std::vector<double> out;
        for (const auto& x : xs) out.push_back(f(x));
        return out;
    }
};

double flat(const std::vector<double>&) { return 1.5; }

RestartRule ipop(int patience, double tolerance = 0.0, double tol_x = 0.0) {
    return {Restarts::Ipop, patience, tolerance, tol_x};
}

TEST(GaitSearchIpop, BadArgumentsThrow) {
    EXPECT_THROW(Search(Optimizer::Sade, 4, 8, 0.3, 1, ipop(3)), std::invalid_argument);
    EXPECT_NO_THROW(Search(Optimizer::Sade, 4, 8, 0.3, 1, RestartRule{}));
    EXPECT_NO_THROW(Search(Optimizer::Xnes, 4, 8, 0.3, 1, ipop(3)));
    EXPECT_THROW(Search(Optimizer::Cmaes, 4, 8, 0.3, 1, ipop(-1)), std::invalid_argument);
    EXPECT_THROW(Search(Optimizer::Cmaes, 4, 8, 0.3, 1, ipop(3, -0.1)), std::invalid_argument);
    EXPECT_THROW(Search(Optimizer::Cmaes, 4, 8, 0.3, 1, ipop(3, std::nan(""))), std::invalid_argument);
    EXPECT_THROW(Search(Optimizer::Cmaes, 4, 8, 0.3, 1, ipop(3, 0.0, -1.0)), std::invalid_argument);
    EXPECT_THROW(Search(Optimizer::Cmaes, 4, 8, 0.3, 1, ipop(3, 0.0, INFINITY)), std::invalid_argument);
    EXPECT_EQ(restart_seed(9, 0), 9u);
    EXPECT_NE(restart_seed(9, 1), restart_seed(9, 2));
    EXPECT_NE(restart_seed(9, 1), restart_seed(10, 1));
}

// On a flat function every start stagnates after `patience` generations: the
// next generation is a fresh start from uniform points with twice the
// population, announced by next_batch_size() before it is evaluated.
TEST(GaitSearchIpop, AFlatFunctionRestartsWithDoubledPopulations) {
    RecordingEvaluator eval;
    eval.f = flat;
    Search s(Optimizer::Cmaes, 3, 6, 0.2, 5, ipop(2));
    s.initialise(std::ref(eval));
    EXPECT_FALSE(s.restart_pending());
    s.step(std::ref(eval));
    EXPECT_FALSE(s.restart_pending());
    s.step(std::ref(eval));   // generation 2: B_2 - B_0 = 0 <= 0
    EXPECT_TRUE(s.restart_pending());
    EXPECT_EQ(s.stalled_generations(), 2);
    EXPECT_FALSE(s.collapsed());
    EXPECT_EQ(s.population_size(), 6);
    EXPECT_EQ(s.next_batch_size(), 12);
    const Candidate first = s.champion();
    s.step(std::ref(eval));   // generation 3: restart 1
    EXPECT_EQ(s.restarts(), 1);
    EXPECT_EQ(s.population_size(), 12);
    EXPECT_EQ(s.population().size(), 12u);
    EXPECT_EQ(s.restart_generations(), std::vector<int>{3});
    EXPECT_EQ(s.champion().x, first.x) << "the champion (the first of equals) is kept across restarts";
    for (const auto& x : eval.points.back())
        for (double v : x) {
            EXPECT_GE(v, 0.0);
            EXPECT_LT(v, 1.0);
        }
    EXPECT_NE(eval.points.back().front(), eval.points.front().front()) << "a new seed for the new start";
    for (int g = 0; g < 3; ++g) s.step(std::ref(eval));   // generations 4, 5 and restart 2 at 6
    EXPECT_EQ(s.restarts(), 2);
    EXPECT_EQ(s.population_size(), 24);
    EXPECT_EQ(s.restart_generations(), (std::vector<int>{3, 6}));
    EXPECT_EQ(eval.batches, (std::vector<std::size_t>{6, 6, 6, 12, 12, 12, 24}));
    EXPECT_EQ(s.evaluations(), 78);
    EXPECT_EQ(s.generation(), 6);
    EXPECT_EQ(s.history().size(), 78u);

    // Without the rule the same function never restarts.
    RecordingEvaluator none_eval;
    none_eval.f = flat;
    Search none(Optimizer::Cmaes, 3, 6, 0.2, 5);
    none.initialise(std::ref(none_eval));
    for (int g = 0; g < 6; ++g) {
        EXPECT_EQ(none.next_batch_size(), 6);
        none.step(std::ref(none_eval));
    }
    EXPECT_EQ(none.restarts(), 0);
    EXPECT_EQ(none_eval.batches, std::vector<std::size_t>(7, 6));
}

// A start whose candidates have all come closer than tol_x in every
// coordinate restarts at once, whatever the patience.
TEST(GaitSearchIpop, ACollapsedStartRestarts) {
    RecordingEvaluator eval;
    Search s(Optimizer::Cmaes, 4, 8, 0.02, 2, ipop(1000, 0.0, 0.3));
    s.initialise(std::ref(eval));
    EXPECT_FALSE(s.restart_pending()) << "the uniform first batch is spread out";
    s.step(std::ref(eval));
    EXPECT_TRUE(s.restart_pending());
    EXPECT_TRUE(s.collapsed());
    s.step(std::ref(eval));
    EXPECT_EQ(s.restarts(), 1);
    EXPECT_FALSE(s.restart_pending());
}

TEST(GaitSearchIpop, DefaultPatienceIsHansensWindow) {
    RecordingEvaluator eval;
    eval.f = flat;
    Search s(Optimizer::Cmaes, 6, 10, 0.3, 1, ipop(0));
    EXPECT_EQ(s.patience(), 10 + 18);   // 10 + ceil(30 * 6 / 10)
    s.initialise(std::ref(eval));
    for (int g = 0; g < 27; ++g) s.step(std::ref(eval));
    EXPECT_FALSE(s.restart_pending());
    s.step(std::ref(eval));
    EXPECT_TRUE(s.restart_pending());
    s.step(std::ref(eval));
    EXPECT_EQ(s.population_size(), 20);
    EXPECT_EQ(s.patience(), 10 + 9);    // 10 + ceil(30 * 6 / 20)
    EXPECT_EQ(Search(Optimizer::Cmaes, 6, 10, 0.3, 1, ipop(7)).patience(), 7);
}

class IpopOptimizer : public ::testing::TestWithParam<Optimizer> {};

// The same seed repeats a restarting search exactly; replaying its history at
// any generation (mid-start, with a restart pending, or at a restart's first
// batch) and continuing gives the uninterrupted search, bit for bit.
TEST_P(IpopOptimizer, ReplayAfterRestartsEqualsTheUninterruptedSearch) {
    const RestartRule rule = ipop(3, 0.0, 1e-9);
    auto run = [&](RecordingEvaluator& eval, int generations) {
        Search s(GetParam(), 4, 6, 0.3, 11, rule);
        s.initialise(std::ref(eval));
        for (int g = 0; g < generations; ++g) s.step(std::ref(eval));
        return s;
    };
    RecordingEvaluator a, b;
    const Search whole = run(a, 30), again = run(b, 30);
    ASSERT_GE(whole.restarts(), 2) << "the plateaus should stall every start";
    EXPECT_EQ(whole.history(), again.history());
    EXPECT_EQ(whole.champion().x, again.champion().x);
    EXPECT_EQ(whole.restart_generations(), again.restart_generations());
    // Generations to stop at: each restart's first batch, the one before it (restart pending), one after.
    std::vector<int> stops;
    for (int g : whole.restart_generations())
        for (int stop : {g - 1, g, g + 1})
            if (stop <= 30) stops.push_back(stop);
    for (int stop : stops) {
        RecordingEvaluator first;
        const Search part = run(first, stop);
        Search resumed(GetParam(), 4, 6, 0.3, 11, rule);
        resumed.replay(part.history(), stop);
        EXPECT_EQ(resumed.restarts(), part.restarts()) << stop;
        EXPECT_EQ(resumed.restart_pending(), part.restart_pending()) << stop;
        EXPECT_EQ(resumed.next_batch_size(), part.next_batch_size()) << stop;
        RecordingEvaluator rest;
        for (int g = stop; g < 30; ++g) resumed.step(std::ref(rest));
        EXPECT_EQ(resumed.history(), whole.history()) << stop;
        ASSERT_EQ(resumed.population().size(), whole.population().size()) << stop;
        for (std::size_t i = 0; i < whole.population().size(); ++i)
            EXPECT_EQ(resumed.population()[i].x, whole.population()[i].x) << stop << " " << i;
        EXPECT_EQ(resumed.champion().x, whole.champion().x) << stop;
        EXPECT_EQ(bits(resumed.champion().fitness), bits(whole.champion().fitness)) << stop;
        EXPECT_EQ(resumed.restart_generations(), whole.restart_generations()) << stop;
        EXPECT_EQ(resumed.population_size(), whole.population_size()) << stop;
    }
    // A history replayed under another rule does not fit its generations.
    Search other(GetParam(), 4, 6, 0.3, 11);
    EXPECT_THROW(other.replay(whole.history(), 30), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Gait, IpopOptimizer, ::testing::Values(Optimizer::Cmaes, Optimizer::Xnes),
                         [](const auto& info) { return to_string(info.param); });

INSTANTIATE_TEST_SUITE_P(Gait, EveryOptimizer, ::testing::Values(Optimizer::Cmaes, Optimizer::Xnes, Optimizer::Sade),
                         [](const auto& info) { return to_string(info.param); });

} // namespace
} // namespace cic::gait
