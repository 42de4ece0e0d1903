#pragma once
// sin and cos for tree evaluation: branch-free, so the evaluator's block loops
// vectorise, and made of plain double arithmetic (no FMA, no libm), so results
// are the same on every x86-64 and in every build that keeps IEEE semantics
// (no -ffast-math; C++20 ISO mode already disables FMA contraction).
//
// Method (fdlibm's): n = nearest integer to x * 2/pi; r = x - n pi/2 with pi/2
// split into three 33-bit parts (exact products for |n| < 2^20) and a fourth
// 53-bit part, with exact TwoSum steps, giving r = hi + lo; then fdlibm's
// kernels __kernel_sin / __kernel_cos on [-pi/4, pi/4] and the quadrant n mod 4.
//
// Accuracy: within 1 ulp of the correctly rounded result for |x| <= kTrigBound
// (tested: at most 1 ulp from glibc's std::sin/std::cos, see tests/tree/trig_test.cpp
// and docs/primitives.md). Outside that range, and for inf and NaN, the
// evaluator calls std::sin / std::cos instead (see tree_sin / tree_cos below).
#include <bit>
#include <cmath>
#include <cstdint>

namespace cic::tree {

// Arguments with |x| above this go to std::sin / std::cos.
inline constexpr double kTrigBound = 1e5;

namespace trig_detail {

constexpr double kInvPio2 = 6.36619772367581382433e-01;   // 2/pi
constexpr double kShift = 0x1.8p52;                        // x + kShift - kShift rounds x to an integer
constexpr double kPio2_1 = 1.57079632673412561417e+00;    // first 33 bits of pi/2
constexpr double kPio2_2 = 6.07710050630396597660e-11;    // next 33 bits
constexpr double kPio2_3 = 2.02226624871116645580e-21;    // next 33 bits
constexpr double kPio2_3t = 8.47842766036889956997e-32;   // pi/2 - kPio2_1 - kPio2_2 - kPio2_3

constexpr double S1 = -1.66666666666666324348e-01;
constexpr double S2 = 8.33333333332248946124e-03;
constexpr double S3 = -1.98412698298579493134e-04;
constexpr double S4 = 2.75573137070700676789e-06;
constexpr double S5 = -2.50507602534068634195e-08;
constexpr double S6 = 1.58969099521155010221e-10;

constexpr double C1 = 4.16666666666666019037e-02;
constexpr double C2 = -1.38888888888741095749e-03;
constexpr double C3 = 2.48015872894767294178e-05;
constexpr double C4 = -2.75573143513906633035e-07;
constexpr double C5 = 2.08757232129817482790e-09;
constexpr double C6 = -1.13596475577881948265e-11;

// s + e == a + b exactly (Knuth's TwoSum; needs no ordering of |a|, |b|).
inline double two_sum(double a, double b, double& e) {
    const double s = a + b;
    const double bb = s - a;
    e = (a - (s - bb)) + (b - bb);
    return s;
}

// fdlibm __kernel_sin(x, y, 1): sin(x + y) for |x| <= pi/4, |y| tiny.
inline double kernel_sin(double x, double y) {
    const double z = x * x;
    const double v = z * x;
    const double r = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
    return x - ((z * (0.5 * y - v * r) - y) - v * S1);
}

// FreeBSD's __kernel_cos(x, y): cos(x + y) for |x| <= pi/4, |y| tiny.
inline double kernel_cos(double x, double y) {
    const double z = x * x;
    double w = z * z;
    const double r = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
    const double hz = 0.5 * z;
    w = 1.0 - hz;
    return w + (((1.0 - w) - hz) + (z * r - x * y));
}

// Reduces |x| <= kTrigBound to hi + lo in [-pi/4, pi/4] (about); returns n mod 4
// in the low bits of the result.
inline std::uint64_t reduce(double x, double& hi, double& lo) {
    const double t = x * kInvPio2 + kShift;
    const double fn = t - kShift;
    const double r1 = x - fn * kPio2_1;                 // exact (fdlibm's argument)
    double e1, e2;
    const double r2 = two_sum(r1, -(fn * kPio2_2), e1);  // fn * kPio2_2 is exact
    const double r3 = two_sum(r2, -(fn * kPio2_3), e2);  // and so is fn * kPio2_3
    // The kernels take hi + lo with |lo| at most a few ulp of 1 (any |hi|), which
    // they use to first order only; not renormalising keeps the sign of -0.
    hi = r3;
    lo = (e1 + e2) - fn * kPio2_3t;
    // t = 1.5 * 2^52 + n, so its low mantissa bits are n (two's complement mod 2^51).
    return std::bit_cast<std::uint64_t>(t);
}

// sin(r + q pi/2) from s = sin(r) and c = cos(r): c for odd q, negated for
// q mod 4 in {2, 3}. Integer masks only (SSE2 has no 64-bit compare), so the
// select vectorises on every x86-64 level.
inline double quadrant(double s, double c, std::uint64_t q) {
    const std::uint64_t odd = std::uint64_t{0} - (q & 1);   // all ones when q is odd
    const std::uint64_t bits = (std::bit_cast<std::uint64_t>(c) & odd) | (std::bit_cast<std::uint64_t>(s) & ~odd);
    return std::bit_cast<double>(bits ^ ((q & 2) << 62));
}

} // namespace trig_detail

// sin(x) for |x| <= kTrigBound (any other input gives a finite, meaningless value:
// callers check the range). Branch-free.
inline double sin_kernel(double x) {
    using namespace trig_detail;
    double hi, lo;
    const std::uint64_t q = reduce(x, hi, lo);
    return quadrant(kernel_sin(hi, lo), kernel_cos(hi, lo), q);
}

// cos(x) for |x| <= kTrigBound, as sin_kernel.
inline double cos_kernel(double x) {
    using namespace trig_detail;
    double hi, lo;
    const std::uint64_t q = reduce(x, hi, lo) + 1;   // cos(x) = sin(x + pi/2)
    return quadrant(kernel_sin(hi, lo), kernel_cos(hi, lo), q);
}

// Scalar versions with the fall-back: what the evaluator computes for one value.
inline double tree_sin(double x) { return std::fabs(x) <= kTrigBound ? sin_kernel(x) : std::sin(x); }
inline double tree_cos(double x) { return std::fabs(x) <= kTrigBound ? cos_kernel(x) : std::cos(x); }

} // namespace cic::tree
