// Reference data from the settings: benchmarks, expressions, equidistant sampling.
#include <cmath>
#include <numbers>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cic/core/error.hpp"
#include "cic/experiments/symreg/problem.hpp"

using namespace cic::symreg;
using cic::InputError;
using testing::HasSubstr;

namespace {

SymregConfig config(std::string target, bool own_sampling = true, int samples = 20, double lo = -1, double hi = 1) {
    SymregConfig c;
    c.target = std::move(target);
    c.benchmark_sampling = own_sampling;
    c.samples = samples;
    c.range_min = lo;
    c.range_max = hi;
    return c;
}

std::string error_of(const SymregConfig& c) {
    try {
        make_dataset(c, "");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

} // namespace

TEST(SymregDataset, Koza1OwnSamplingIs20UniformPointsOfTheQuartic) {
    const auto d = make_dataset(config("Koza-1"), "");   // names are case-insensitive
    ASSERT_EQ(d.variables(), 1);
    ASSERT_EQ(d.rows(), 20u);
    std::set<double> distinct;
    for (std::size_t r = 0; r < d.rows(); ++r) {
        const double x = d.columns[0][r];
        EXPECT_GE(x, -1.0);
        EXPECT_LT(x, 1.0);
        EXPECT_EQ(d.target[r], x * x * x * x + x * x * x + x * x + x);
        distinct.insert(x);
    }
    EXPECT_EQ(distinct.size(), 20u);
    EXPECT_THAT(d.description, HasSubstr("koza-1"));
}

TEST(SymregDataset, Koza1AtKnownPoints) {
    const auto d = make_dataset(config("koza-1", false, 21, -1, 1), "");
    ASSERT_EQ(d.rows(), 21u);
    EXPECT_DOUBLE_EQ(d.columns[0][0], -1.0);
    EXPECT_DOUBLE_EQ(d.target[0], 0.0);            // 1 - 1 + 1 - 1
    EXPECT_NEAR(d.columns[0][10], 0.0, 1e-15);
    EXPECT_NEAR(d.target[10], 0.0, 1e-15);
    EXPECT_NEAR(d.target[15], 0.9375, 1e-12);      // x = 0.5
    EXPECT_DOUBLE_EQ(d.target[20], 4.0);           // x = 1
}

TEST(SymregDataset, BenchmarkPointsAreTheSameOnEveryCall) {
    for (const char* name : {"koza-1", "nguyen-9", "keijzer-5", "vladislavleva-4"}) {
        const auto a = make_dataset(config(name), "");
        const auto b = make_dataset(config(name), "");
        EXPECT_EQ(a.columns, b.columns) << name;
        EXPECT_EQ(a.target, b.target) << name;
    }
    // ... and differ between benchmarks with the same ranges (own seeds).
    EXPECT_NE(make_dataset(config("koza-1"), "").columns, make_dataset(config("koza-2"), "").columns);
}

TEST(SymregDataset, Nguyen7SpotChecks) {
    const auto own = make_dataset(config("nguyen-7"), "");
    ASSERT_EQ(own.rows(), 20u);
    for (std::size_t r = 0; r < own.rows(); ++r) {
        const double x = own.columns[0][r];
        EXPECT_GE(x, 0.0);
        EXPECT_LT(x, 2.0);
        EXPECT_NEAR(own.target[r], std::log(x + 1) + std::log(x * x + 1), 1e-15);
    }
    const auto d = make_dataset(config("nguyen-7", false, 3, 0, 2), "");
    EXPECT_DOUBLE_EQ(d.target[0], 0.0);
    EXPECT_DOUBLE_EQ(d.target[1], 2 * std::numbers::ln2);
    EXPECT_DOUBLE_EQ(d.target[2], std::log(15.0));
}

TEST(SymregDataset, Keijzer1IsAGridWithStep0_1) {
    const auto d = make_dataset(config("keijzer-1"), "");
    ASSERT_EQ(d.rows(), 21u);
    EXPECT_DOUBLE_EQ(d.columns[0].front(), -1.0);
    EXPECT_NEAR(d.columns[0].back(), 1.0, 1e-12);
    EXPECT_NEAR(d.columns[0][13], 0.3, 1e-12);
    EXPECT_NEAR(d.target[13], 0.09 * std::sin(0.6 * std::numbers::pi), 1e-12);  // 0.3 x sin(2 pi x)
}

TEST(SymregDataset, GridSizesFollowEcj) {
    EXPECT_EQ(make_dataset(config("keijzer-4"), "").rows(), 201u);        // E[0, 10, 0.05]
    EXPECT_EQ(make_dataset(config("keijzer-6"), "").rows(), 50u);         // E[1, 50, 1]
    EXPECT_EQ(make_dataset(config("pagie-1"), "").rows(), 26u * 26u);     // E[-5, 5, 0.4]^2
    EXPECT_EQ(make_dataset(config("vladislavleva-2"), "").rows(), 100u);  // E[0.05, 10, 0.1]
    EXPECT_EQ(make_dataset(config("vladislavleva-3"), "").rows(), 600u);  // 100 x E[0.05, 10.05, 2]
    EXPECT_EQ(make_dataset(config("keijzer-5"), "").variables(), 3);
    EXPECT_EQ(make_dataset(config("vladislavleva-4"), "").rows(), 1024u);
}

TEST(SymregDataset, EveryBenchmarkBuildsFiniteData) {
    const auto names = benchmark_names();
    EXPECT_EQ(names.size(), 37u);  // koza 3 + nguyen 10 + keijzer 15 + pagie 1 + vladislavleva 8
    for (const auto& n : names) {
        const auto d = make_dataset(config(n), "");
        EXPECT_GT(d.rows(), 0u) << n;
        for (double t : d.target) ASSERT_TRUE(std::isfinite(t)) << n;
    }
}

TEST(SymregDataset, EquidistantIncludesBothEnds) {
    const auto v = equidistant(20, -1.0, 0.9);
    ASSERT_EQ(v.size(), 20u);
    EXPECT_EQ(v.front(), -1.0);
    EXPECT_EQ(v.back(), 0.9);
    for (std::size_t i = 1; i < v.size(); ++i) EXPECT_NEAR(v[i] - v[i - 1], 0.1, 1e-12);
    EXPECT_EQ(equidistant(1, 2.0, 3.0), std::vector<double>{2.0});
    EXPECT_THROW(equidistant(0, 0.0, 1.0), std::invalid_argument);
}

TEST(SymregDataset, ExpressionTargetsUseEquidistantPointsAndAGrid) {
    const auto d = make_dataset(config("x^2", false, 5, -2, 2), "");
    EXPECT_EQ(d.columns[0], (std::vector<double>{-2, -1, 0, 1, 2}));
    EXPECT_EQ(d.target, (std::vector<double>{4, 1, 0, 1, 4}));

    const auto m = make_dataset(config("x-1", false, 3, 0, 1), "");   // not a benchmark name
    EXPECT_EQ(m.target, (std::vector<double>{-1, -0.5, 0}));

    const auto g = make_dataset(config("x + 10*y", false, 3, 0, 1), "");
    ASSERT_EQ(g.variables(), 2);
    ASSERT_EQ(g.rows(), 9u);   // full grid, x0 slowest
    EXPECT_EQ(g.columns[0], (std::vector<double>{0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1}));
    EXPECT_EQ(g.columns[1], (std::vector<double>{0, 0.5, 1, 0, 0.5, 1, 0, 0.5, 1}));
    EXPECT_DOUBLE_EQ(g.target[5], 10.5);
}

TEST(SymregDataset, BadInputIsRefusedClearly) {
    EXPECT_THAT(error_of(config("koza-9")), HasSubstr("unknown symreg benchmark 'koza-9'"));
    EXPECT_THAT(error_of(config("koza-9")), HasSubstr("nguyen-10"));
    EXPECT_THAT(error_of(config("Korns-1")), HasSubstr("unknown symreg benchmark 'Korns-1'"));
    EXPECT_THAT(error_of(config("quartic")), HasSubstr("known benchmarks: koza-1"));
    EXPECT_THAT(error_of(config("x^", false)), HasSubstr("column 3"));
    EXPECT_THAT(error_of(config("log(x)", false, 5, -1, 1)), HasSubstr("not finite at x0 = -1"));
    EXPECT_THAT(error_of(config("x", false, 0)), HasSubstr("samples must be >= 1"));
    EXPECT_THAT(error_of(config("x", false, 5, 1, -1)), HasSubstr("range_min <= range_max"));
    EXPECT_THAT(error_of(config("x0+x1+x2+x3+x4+x5+x6+x7", false, 20)), HasSubstr("10^7"));
    auto c = config("koza-1");
    c.hit_tolerance = -1;
    EXPECT_THAT(error_of(c), HasSubstr("hit tolerance"));
}
