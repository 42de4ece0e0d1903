#pragma once
// Statistics for comparing configurations over seeds (`cic compare`, docs/statistics.md):
// descriptive summaries, the two-sided Mann-Whitney U test as scipy.stats.mannwhitneyu
// computes it, the Vargha-Delaney A12 effect size and Holm's step-down correction.
// Pure functions without I/O. Every function that takes samples throws
// std::invalid_argument when a sample is empty or holds a NaN.
#include <span>
#include <string_view>
#include <vector>

namespace cic::report::stats {

// Quantile q (0..1) of a sample, numpy's default "linear" definition (Hyndman and
// Fan type 7): sort, h = (n-1)q, then interpolate linearly between the values at
// floor(h) and floor(h)+1 (0-based). Also what R's quantile() does by default.
double quantile(std::span<const double> sample, double q);

struct Descriptive {
    std::size_t n = 0;
    double mean = 0;
    double sd = 0;       // sample standard deviation (divides by n-1); 0 when n == 1
    double median = 0;
    double q1 = 0, q3 = 0;   // quantile(0.25), quantile(0.75) as above
    double iqr = 0;          // q3 - q1
    double min = 0, max = 0;
};
Descriptive describe(std::span<const double> sample);

// How the p-value of the Mann-Whitney U test is found.
// Auto follows scipy's method="auto" (as scipy 1.10, Debian 12's, implements it):
// Exact when at least one sample has at most 8 values and no value occurs twice
// in the pooled data, Asymptotic otherwise. A forced Exact ignores ties (U is
// rounded down, as scipy does).
enum class MwuMethod { Auto, Exact, Asymptotic };

struct MannWhitney {
    double u = 0;         // U of the first sample: pairs (x, y) with x > y, plus half the ties
    double u2 = 0;        // U of the second sample: n1*n2 - u
    double p = 1;         // two-sided p-value, capped at 1
    bool exact = false;   // p from the exact null distribution (else the normal approximation)
    double z = 0;         // asymptotic only: the standardised statistic of max(u, u2) (continuity corrected)
};

// Two-sided Mann-Whitney U test of x against y, as scipy.stats.mannwhitneyu(x, y)
// with its defaults (alternative="two-sided", use_continuity=True, method="auto").
// Exact: p = 2 P(U >= max(u, u2)) under H0, from the counts of rank arrangements
// (a DP over f(m, n, k) = f(m-1, n, k-n) + f(m, n-1, k)).
// Asymptotic: z = (max(u, u2) - n1 n2 / 2 - 0.5) / s with the tie-corrected
// s = sqrt(n1 n2 / 12 * ((n+1) - sum(t^3 - t) / (n (n-1)))), p = 2 (1 - Phi(z)).
MannWhitney mann_whitney_u(std::span<const double> x, std::span<const double> y, MwuMethod method = MwuMethod::Auto);

// P(U >= u) for U the statistic of m values against n values without ties, under
// H0 (every arrangement of ranks equally likely). The exact test uses 2 of this.
double mann_whitney_exact_sf(int u, int m, int n);

// Vargha-Delaney A12: the probability that a value drawn from x exceeds one drawn
// from y, ties counting half: (#(x > y) + #(x == y) / 2) / (n1 n2) = u / (n1 n2).
double vargha_delaney_a12(std::span<const double> x, std::span<const double> y);

// A confidence interval of A12, which is the area under the ROC curve of x
// against y: A12 +- z sqrt(S10 / m + S01 / n) (DeLong et al. 1988), clamped
// to [0, 1], where S10 is the sample variance (n-1) over the m values of x of
// the share of y each beats (ties half), S01 the same over y, and a sample of
// one value contributes no variance. z = 1.96 gives 95%. Samples that do not
// overlap give an interval of width 0: read it with n. Throws
// std::invalid_argument for z <= 0.
struct Interval {
    double low = 0, high = 0;
};
Interval a12_interval(std::span<const double> x, std::span<const double> y, double z = 1.959963984540054);

// The conventional magnitude of A12 (Vargha and Delaney 2000), symmetric around
// 0.5: with m = max(a, 1 - a), negligible when m < 0.56, small when m < 0.64,
// medium when m < 0.71, large otherwise. A tolerance of 1e-9 keeps e.g. 0.44
// (m = 1 - 0.44, a hair below 0.56 in binary) on the same side as 0.56.
enum class EffectMagnitude { Negligible, Small, Medium, Large };
EffectMagnitude a12_magnitude(double a12);
std::string_view to_string(EffectMagnitude m);

// The smallest two-sided p-value the exact Mann-Whitney test can give for groups
// of na and nb values (no ties): the two most extreme orderings of C(na + nb, na),
// min(1, 2 / C(na + nb, na)). When it is not below alpha, no outcome of that
// comparison can be significant (3 and 3 runs: 0.1). Throws
// std::invalid_argument when a group is empty.
double smallest_attainable_p(std::size_t na, std::size_t nb);

// Holm's step-down adjustment of a family of p-values: sort them ascending
// p(1) <= ... <= p(m); adjusted p(i) = max over j <= i of min(1, (m - j + 1) p(j)).
// Returned in the order given. Rejecting where adjusted p < alpha controls the
// family-wise error rate at alpha. Throws std::invalid_argument for a NaN or a
// value outside [0, 1]; an empty family gives an empty result.
std::vector<double> holm_adjust(std::span<const double> p_values);

} // namespace cic::report::stats
