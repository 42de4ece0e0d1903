// The evaluator's own sin/cos (include/cic/tree/trig.hpp) against glibc's.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "cic/core/rng.hpp"
#include "cic/tree/eval.hpp"
#include "cic/tree/trig.hpp"

using namespace cic;
using namespace cic::tree;

namespace {

// Distance in units in the last place: doubles mapped onto a monotone integer line.
std::uint64_t ulp_distance(double a, double b) {
    auto line = [](double v) {
        const auto bits = std::bit_cast<std::int64_t>(v);
        return bits < 0 ? std::numeric_limits<std::int64_t>::min() - bits : bits;
    };
    const std::int64_t x = line(a), y = line(b);
    return x > y ? static_cast<std::uint64_t>(x) - static_cast<std::uint64_t>(y)
                 : static_cast<std::uint64_t>(y) - static_cast<std::uint64_t>(x);
}

// Points over the documented range: uniform, log-uniform magnitudes down to
// subnormals, and the hard cases right next to multiples of pi/2.
std::vector<double> test_points() {
    Rng rng(2024);
    std::vector<double> xs;
    for (int i = 0; i < 60000; ++i) xs.push_back(rng.uniform(-kTrigBound, kTrigBound));
    for (int i = 0; i < 60000; ++i) xs.push_back(rng.uniform(-10.0, 10.0));
    for (int i = 0; i < 30000; ++i) {
        const double m = std::pow(10.0, rng.uniform(-320.0, 5.0));
        xs.push_back(rng.bernoulli(0.5) ? m : -m);
    }
    for (int n = -63661; n <= 63661; n += 7) {
        double x = n * (std::numbers::pi / 2);
        for (int k = 0; k < 3; ++k) {
            xs.push_back(x);
            x = std::nextafter(x, std::numeric_limits<double>::infinity());
        }
    }
    xs.insert(xs.end(), {0.0, -0.0, 1e-310, -1e-310, kTrigBound, -kTrigBound, std::numbers::pi / 4,
                         std::numbers::pi / 2, std::numbers::pi});
    return xs;
}

} // namespace

TEST(Trig, WithinOneUlpOfLibmOnTheDocumentedRange) {
    std::uint64_t worst_sin = 0, worst_cos = 0;
    double at_sin = 0, at_cos = 0;
    for (const double x : test_points()) {
        ASSERT_LE(std::fabs(x), kTrigBound);
        const auto ds = ulp_distance(sin_kernel(x), std::sin(x));
        const auto dc = ulp_distance(cos_kernel(x), std::cos(x));
        if (ds > worst_sin) { worst_sin = ds; at_sin = x; }
        if (dc > worst_cos) { worst_cos = dc; at_cos = x; }
    }
    EXPECT_LE(worst_sin, 1u) << "sin at " << at_sin;
    EXPECT_LE(worst_cos, 1u) << "cos at " << at_cos;
}

TEST(Trig, SignedZeroAndExactSmallCases) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(sin_kernel(-0.0)), std::bit_cast<std::uint64_t>(-0.0));
    EXPECT_EQ(sin_kernel(0.0), 0.0);
    EXPECT_EQ(cos_kernel(0.0), 1.0);
    EXPECT_EQ(cos_kernel(-0.0), 1.0);
    EXPECT_EQ(sin_kernel(1e-300), 1e-300);
}

TEST(Trig, OutsideTheRangeTheEvaluatorFallsBackToLibmExactly) {
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<double> xs{std::nextafter(kTrigBound, inf), -2e5, 1e6, 1e22, -1e300,
                                 std::numeric_limits<double>::max(), inf, -inf,
                                 std::numeric_limits<double>::quiet_NaN(), 0.5, -3.0};
    const double* col = xs.data();
    std::vector<double> s(xs.size()), c(xs.size());
    evaluate(Tree::parse("(sin x0)"), std::span<const double* const>(&col, 1), xs.size(), s);
    evaluate(Tree::parse("(cos x0)"), std::span<const double* const>(&col, 1), xs.size(), c);
    for (std::size_t i = 0; i < xs.size(); ++i) {
        const double want_s = std::fabs(xs[i]) <= kTrigBound ? sin_kernel(xs[i]) : std::sin(xs[i]);
        const double want_c = std::fabs(xs[i]) <= kTrigBound ? cos_kernel(xs[i]) : std::cos(xs[i]);
        EXPECT_EQ(std::bit_cast<std::uint64_t>(s[i]), std::bit_cast<std::uint64_t>(want_s)) << xs[i];
        EXPECT_EQ(std::bit_cast<std::uint64_t>(c[i]), std::bit_cast<std::uint64_t>(want_c)) << xs[i];
        EXPECT_EQ(std::bit_cast<std::uint64_t>(s[i]), std::bit_cast<std::uint64_t>(tree_sin(xs[i])));
        EXPECT_EQ(std::bit_cast<std::uint64_t>(c[i]), std::bit_cast<std::uint64_t>(tree_cos(xs[i])));
    }
    EXPECT_TRUE(std::isnan(s[6]));   // sin(inf) stays non-finite: the clamped re-run still sees it
}

TEST(Trig, BlockPathAgreesWithTheScalarFunctions) {
    // 64-row blocks, a tail, and small batches all give tree_sin / tree_cos bit for bit.
    Rng rng(5);
    std::vector<double> xs(64 * 2 + 13);
    for (auto& x : xs) x = rng.bernoulli(0.1) ? rng.uniform(-1e7, 1e7) : rng.uniform(-20.0, 20.0);
    const double* col = xs.data();
    for (const std::size_t rows : {xs.size(), std::size_t{20}, std::size_t{3}}) {
        std::vector<double> s(rows), c(rows);
        evaluate(Tree::parse("(sin x0)"), std::span<const double* const>(&col, 1), rows, s);
        evaluate(Tree::parse("(cos x0)"), std::span<const double* const>(&col, 1), rows, c);
        for (std::size_t i = 0; i < rows; ++i) {
            ASSERT_EQ(std::bit_cast<std::uint64_t>(s[i]), std::bit_cast<std::uint64_t>(tree_sin(xs[i]))) << xs[i];
            ASSERT_EQ(std::bit_cast<std::uint64_t>(c[i]), std::bit_cast<std::uint64_t>(tree_cos(xs[i]))) << xs[i];
        }
    }
}
