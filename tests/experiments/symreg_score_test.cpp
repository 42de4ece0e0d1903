// Fitness of a genotype on the reference points (thesis eq. 6.1-6.2).
#include <cmath>

#include <gtest/gtest.h>

#include "cic/tree/tree.hpp"
#include "cic/experiments/symreg/problem.hpp"

using namespace cic::symreg;
using cic::tree::Forest;
using cic::tree::Tree;

namespace {

Dataset koza1() {
    SymregConfig c;
    c.target = "koza-1";
    return make_dataset(c, "");
}

// x^4 + x^3 + x^2 + x, in the same evaluation order as the benchmark's formula.
const char* quartic =
    "(add (add (add (mul (mul (mul x0 x0) x0) x0) (mul (mul x0 x0) x0)) (mul x0 x0)) x0)";

} // namespace

TEST(SymregScore, ExactTargetScoresZeroAndSucceeds) {
    const auto data = koza1();
    std::vector<double> scratch;
    const auto s = score(Forest{Tree::parse(quartic)}, data, 0.01, scratch);
    EXPECT_NEAR(s.fitness, 0.0, 1e-12);
    EXPECT_LE(s.fitness, 0.0);
    EXPECT_EQ(s.hits, 20);
    EXPECT_TRUE(s.success);
}

TEST(SymregScore, WrongTreeIsNegativeSumOfAbsoluteErrors) {
    const auto data = koza1();
    std::vector<double> scratch;
    const auto s = score(Forest{Tree::parse("x0")}, data, 0.01, scratch);
    double expected = 0;
    for (std::size_t r = 0; r < data.rows(); ++r) expected += std::fabs(data.columns[0][r] - data.target[r]);
    EXPECT_LT(s.fitness, 0.0);
    EXPECT_NEAR(s.fitness, -expected, 1e-12);
    EXPECT_LT(s.hits, 20);
    EXPECT_FALSE(s.success);
}

TEST(SymregScore, HitsCountPointsWithinTolerance) {
    Dataset d;
    d.columns = {{0.0, 1.0, 2.0}};
    d.target = {0.005, 1.5, 2.0};
    std::vector<double> scratch;
    const auto s = score(Forest{Tree::parse("x0")}, d, 0.01, scratch);
    EXPECT_EQ(s.hits, 2);
    EXPECT_FALSE(s.success);
    EXPECT_NEAR(s.fitness, -0.505, 1e-12);
    EXPECT_TRUE(score(Forest{Tree::parse("x0")}, d, 0.6, scratch).success);
}

TEST(SymregScore, NonFiniteOutputGetsTheFailedFitnessNeverNaN) {
    Dataset d;
    d.columns = {{1e308, -1e308, 1.0}};
    d.target = {0.0, 0.0, 1.0};
    std::vector<double> scratch;
    // x0^2 overflows (cic clamps it to DBL_MAX); the error sum overflows to inf.
    const auto s = score(Forest{Tree::parse("(mul x0 x0)")}, d, 0.01, scratch);
    EXPECT_EQ(s.fitness, failed_fitness);
    EXPECT_EQ(s.hits, 1);
    EXPECT_FALSE(s.success);
    // A huge but finite error ranks with the failures, not below them.
    d.columns = {{1e200, 1.0}};
    d.target = {0.0, 1.0};
    const auto huge = score(Forest{Tree::parse("(mul x0 x0)")}, d, 0.01, scratch);
    EXPECT_EQ(huge.fitness, failed_fitness);
    EXPECT_FALSE(huge.success);
    // A target that is NaN (only possible in a hand-made Dataset) fails too.
    d.target = {std::nan(""), 1.0};
    EXPECT_EQ(score(Forest{Tree::parse("x0")}, d, 0.01, scratch).fitness, failed_fitness);
}

TEST(SymregScore, UsesTreeZeroOfTheForest) {
    const auto data = koza1();
    std::vector<double> scratch;
    const auto s = score(Forest{Tree::parse(quartic), Tree::parse("x0")}, data, 0.01, scratch);
    EXPECT_TRUE(s.success);
}

TEST(SymregScore, SameInputSameScore) {
    const auto data = koza1();
    const Forest f{Tree::parse("(add (sin x0) (mul x0 (cos x0)))")};
    std::vector<double> s1, s2;
    const auto a = score(f, data, 0.01, s1);
    const auto b = score(f, data, 0.01, s2);
    EXPECT_EQ(a.fitness, b.fitness);
    EXPECT_EQ(a.hits, b.hits);
    EXPECT_EQ(s1, s2);
}

TEST(SymregScore, BadArgumentsThrow) {
    const auto data = koza1();
    std::vector<double> scratch;
    EXPECT_THROW(score(Forest{}, data, 0.01, scratch), std::invalid_argument);
    EXPECT_THROW(score(Forest{Tree::parse("x1")}, data, 0.01, scratch), std::invalid_argument);
}
