#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "cic/core/rng.hpp"

using cic::Rng;

TEST(Rng, SameSeedSameSequence) {
    Rng a(123), b(123), c(124);
    bool differs = false;
    for (int i = 0; i < 1000; ++i) {
        const auto x = a.next();
        ASSERT_EQ(x, b.next());
        differs = differs || x != c.next();
    }
    EXPECT_TRUE(differs);
    // Pinned values: a seed must give the same numbers on every platform and build
    // (saved populations store RNG states; changing the generator breaks resume).
    Rng p(1);
    EXPECT_EQ(p.next(), 0xc5883e370b0926c3ULL);
    EXPECT_EQ(p.next(), 0x021b74b80f71f81cULL);
    EXPECT_EQ(p.next(), 0x268df06749e5c8ceULL);
    Rng q(1);
    EXPECT_EQ(q.below(1000), 771u);
    EXPECT_EQ(q.uniform(), 0.0082314442983671965);
    EXPECT_NE(Rng(0).state(), Rng(1).state());
}

TEST(Rng, StateTextRoundTrips) {
    Rng a(99);
    for (int i = 0; i < 10; ++i) a.next();
    const std::string text = a.state_text();
    EXPECT_EQ(text.size(), 4u * 16u + 3u);
    Rng b(1);
    b.set_state(Rng::parse_state(text));
    EXPECT_EQ(b.state(), a.state());
    for (int i = 0; i < 100; ++i) ASSERT_EQ(a.next(), b.next());
    EXPECT_EQ(Rng::parse_state("  1 2\t3 ABCDEF  "), (Rng::State{1, 2, 3, 0xabcdef}));
}

TEST(Rng, BadStateTextThrows) {
    EXPECT_THROW(Rng::parse_state(""), std::invalid_argument);
    EXPECT_THROW(Rng::parse_state("1 2 3"), std::invalid_argument);
    EXPECT_THROW(Rng::parse_state("1 2 3 4 5"), std::invalid_argument);
    EXPECT_THROW(Rng::parse_state("1 2 3 xyz"), std::invalid_argument);
    EXPECT_THROW(Rng::parse_state("1 2 3 -4"), std::invalid_argument);
    EXPECT_THROW(Rng::parse_state("1 2 3 11112222333344445"), std::invalid_argument);   // 17 digits
    EXPECT_THROW(Rng::parse_state("0 0 0 0"), std::invalid_argument);
    Rng r;
    EXPECT_THROW(r.set_state({0, 0, 0, 0}), std::invalid_argument);
}

TEST(Rng, BelowStaysInRangeAndIsRoughlyUniform) {
    Rng r(7);
    EXPECT_THROW(r.below(0), std::invalid_argument);
    EXPECT_EQ(r.below(1), 0u);
    std::vector<int> counts(10);
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        const auto v = r.below(10);
        ASSERT_LT(v, 10u);
        ++counts[v];
    }
    double chi = 0;
    for (int c : counts) chi += (c - n / 10.0) * (c - n / 10.0) / (n / 10.0);
    EXPECT_LT(chi, 27.88);   // 9 degrees of freedom, 0.999 quantile
    const std::uint64_t huge = (std::uint64_t{1} << 63) + 12345;
    for (int i = 0; i < 1000; ++i) ASSERT_LT(r.below(huge), huge);
    for (int i = 0; i < 1000; ++i) {
        const int v = r.between(-3, 3);
        ASSERT_GE(v, -3);
        ASSERT_LE(v, 3);
    }
    EXPECT_THROW(r.between(2, 1), std::invalid_argument);
}

TEST(Rng, UniformAndNormalMoments) {
    Rng r(8);
    double sum = 0, sum2 = 0, usum = 0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        const double u = r.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        usum += u;
        const double z = r.normal();
        sum += z;
        sum2 += z * z;
    }
    EXPECT_NEAR(usum / n, 0.5, 0.005);
    EXPECT_NEAR(sum / n, 0.0, 0.02);
    EXPECT_NEAR(sum2 / n, 1.0, 0.02);
    for (int i = 0; i < 1000; ++i) {
        const double v = r.uniform(-2.0, 5.0);
        ASSERT_GE(v, -2.0);
        ASSERT_LT(v, 5.0);
    }
}

