// Descriptive statistics, Mann-Whitney U, Vargha-Delaney A12 and Holm's correction.
#include "cic/report/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace cic::report::stats {
namespace {

void check_sample(std::span<const double> sample, const char* what) {
    if (sample.empty()) throw std::invalid_argument(std::string(what) + ": empty sample");
    for (double v : sample)
        if (std::isnan(v)) throw std::invalid_argument(std::string(what) + ": sample holds a NaN");
}

// numpy's _lerp: a + (b - a) t, computed from the nearer end for t >= 0.5.
double lerp(double a, double b, double t) {
    const double d = b - a;
    return t >= 0.5 ? b - d * (1.0 - t) : a + d * t;
}

double sorted_quantile(const std::vector<double>& sorted, double q) {
    const double h = static_cast<double>(sorted.size() - 1) * q;
    const double lo = std::floor(h);
    const auto i = static_cast<std::size_t>(lo);
    if (i + 1 >= sorted.size()) return sorted.back();
    return lerp(sorted[i], sorted[i + 1], h - lo);
}

// Rank sum of the first n1 values of the pooled sample (mid-ranks for ties) and
// the tie term sum(t^3 - t) over groups of t equal values.
struct Ranks {
    double r1 = 0;
    double tie_term = 0;
    bool ties = false;
};

Ranks rank_pooled(std::span<const double> x, std::span<const double> y) {
    const std::size_t n = x.size() + y.size();
    std::vector<std::pair<double, bool>> pooled;   // value, from x
    pooled.reserve(n);
    for (double v : x) pooled.emplace_back(v, true);
    for (double v : y) pooled.emplace_back(v, false);
    std::sort(pooled.begin(), pooled.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    Ranks r;
    for (std::size_t i = 0; i < n;) {
        std::size_t j = i + 1;
        while (j < n && pooled[j].first == pooled[i].first) ++j;
        const double t = static_cast<double>(j - i);
        const double mid = (static_cast<double>(i + 1) + static_cast<double>(j)) / 2.0;   // ranks i+1..j
        for (std::size_t k = i; k < j; ++k)
            if (pooled[k].second) r.r1 += mid;
        if (j - i > 1) {
            r.ties = true;
            r.tie_term += t * t * t - t;
        }
        i = j;
    }
    return r;
}

double u_statistic(const Ranks& r, std::size_t n1) {
    const double m = static_cast<double>(n1);
    return r.r1 - m * (m + 1.0) / 2.0;
}

} // namespace

double quantile(std::span<const double> sample, double q) {
    check_sample(sample, "quantile");
    if (!(q >= 0.0 && q <= 1.0)) throw std::invalid_argument("quantile: q must be within [0, 1]");
    std::vector<double> sorted(sample.begin(), sample.end());
    std::sort(sorted.begin(), sorted.end());
    return sorted_quantile(sorted, q);
}

Descriptive describe(std::span<const double> sample) {
    check_sample(sample, "describe");
    std::vector<double> sorted(sample.begin(), sample.end());
    std::sort(sorted.begin(), sorted.end());
    Descriptive d;
    d.n = sorted.size();
    const double n = static_cast<double>(d.n);
    d.mean = std::accumulate(sample.begin(), sample.end(), 0.0) / n;
    if (d.n > 1) {
        double ss = 0;
        for (double v : sample) ss += (v - d.mean) * (v - d.mean);
        d.sd = std::sqrt(ss / (n - 1.0));
    }
    d.median = sorted_quantile(sorted, 0.5);
    d.q1 = sorted_quantile(sorted, 0.25);
    d.q3 = sorted_quantile(sorted, 0.75);
    d.iqr = d.q3 - d.q1;
    d.min = sorted.front();
    d.max = sorted.back();
    return d;
}

double mann_whitney_exact_sf(int u, int m, int n) {
    if (m < 1 || n < 1) throw std::invalid_argument("mann_whitney_exact_sf: sample sizes must be positive");
    const long long mn = static_cast<long long>(m) * n;
    if (u <= 0) return 1.0;
    if (u > mn) return 0.0;
    // P(U >= u) = P(U <= mn - u) by symmetry. pr[i][k] = P(U = k) for i values
    // against j values, built up over j = 0..b; in probabilities the counting
    // recurrence f(i, j, k) = f(i-1, j, k-j) + f(i, j-1, k) becomes
    // p(i, j, k) = i/(i+j) p(i-1, j, k-j) + j/(i+j) p(i, j-1, k): no overflow.
    const int a = std::min(m, n), b = std::max(m, n);
    const auto kmax = static_cast<std::size_t>(mn - u);
    std::vector<std::vector<double>> pr(static_cast<std::size_t>(a) + 1, std::vector<double>(kmax + 1, 0.0));
    for (auto& row : pr) row[0] = 1.0;   // j = 0: U = 0 for certain
    for (int j = 1; j <= b; ++j) {
        const auto shift = static_cast<std::size_t>(j);
        for (int i = 1; i <= a; ++i) {
            const double wi = static_cast<double>(i) / static_cast<double>(i + j);
            const double wj = static_cast<double>(j) / static_cast<double>(i + j);
            auto& row = pr[static_cast<std::size_t>(i)];
            const auto& prev = pr[static_cast<std::size_t>(i) - 1];
            for (std::size_t k = 0; k <= kmax; ++k)
                row[k] = wj * row[k] + (k >= shift ? wi * prev[k - shift] : 0.0);
        }
    }
    double cdf = 0;
    for (double v : pr[static_cast<std::size_t>(a)]) cdf += v;
    return std::min(cdf, 1.0);
}

MannWhitney mann_whitney_u(std::span<const double> x, std::span<const double> y, MwuMethod method) {
    check_sample(x, "mann_whitney_u (first sample)");
    check_sample(y, "mann_whitney_u (second sample)");
    const Ranks ranks = rank_pooled(x, y);
    const double n1 = static_cast<double>(x.size()), n2 = static_cast<double>(y.size());
    MannWhitney r;
    r.u = u_statistic(ranks, x.size());
    r.u2 = n1 * n2 - r.u;
    const double u = std::max(r.u, r.u2);
    if (method == MwuMethod::Auto)
        method = (x.size() > 8 && y.size() > 8) || ranks.ties ? MwuMethod::Asymptotic : MwuMethod::Exact;
    double p = 0;
    if (method == MwuMethod::Exact) {
        r.exact = true;
        p = 2.0 * mann_whitney_exact_sf(static_cast<int>(std::floor(u)), static_cast<int>(x.size()),
                                        static_cast<int>(y.size()));
    } else {
        const double mu = n1 * n2 / 2.0;
        const double n = n1 + n2;
        const double var = n1 * n2 / 12.0 * ((n + 1.0) - ranks.tie_term / (n * (n - 1.0)));
        const double s = std::sqrt(std::max(var, 0.0));
        const double numerator = u - mu - 0.5;
        // s == 0 only when every value is the same: then u == mu, numerator < 0, p = 1.
        r.z = s > 0 ? numerator / s : (numerator < 0 ? -INFINITY : INFINITY);
        p = 2.0 * (0.5 * std::erfc(r.z / std::sqrt(2.0)));
    }
    r.p = std::clamp(p, 0.0, 1.0);
    return r;
}

double vargha_delaney_a12(std::span<const double> x, std::span<const double> y) {
    check_sample(x, "vargha_delaney_a12 (first sample)");
    check_sample(y, "vargha_delaney_a12 (second sample)");
    return u_statistic(rank_pooled(x, y), x.size()) /
           (static_cast<double>(x.size()) * static_cast<double>(y.size()));
}

Interval a12_interval(std::span<const double> x, std::span<const double> y, double z) {
    check_sample(x, "a12_interval (first sample)");
    check_sample(y, "a12_interval (second sample)");
    if (!(z > 0)) throw std::invalid_argument("a12_interval: z must be > 0");
    auto beats = [](double a, double b) { return a > b ? 1.0 : a == b ? 0.5 : 0.0; };
    std::vector<double> v10(x.size(), 0.0), v01(y.size(), 0.0);
    for (std::size_t i = 0; i < x.size(); ++i)
        for (std::size_t j = 0; j < y.size(); ++j) {
            const double s = beats(x[i], y[j]);
            v10[i] += s / static_cast<double>(y.size());
            v01[j] += s / static_cast<double>(x.size());
        }
    auto variance = [](const std::vector<double>& v) {
        if (v.size() < 2) return 0.0;
        double mean = 0;
        for (double a : v) mean += a / static_cast<double>(v.size());
        double ss = 0;
        for (double a : v) ss += (a - mean) * (a - mean);
        return ss / static_cast<double>(v.size() - 1);
    };
    const double a12 = vargha_delaney_a12(x, y);
    const double half = z * std::sqrt(variance(v10) / static_cast<double>(x.size()) +
                                      variance(v01) / static_cast<double>(y.size()));
    return {std::max(0.0, a12 - half), std::min(1.0, a12 + half)};
}

EffectMagnitude a12_magnitude(double a12) {
    if (std::isnan(a12) || a12 < 0.0 || a12 > 1.0)
        throw std::invalid_argument("a12_magnitude: A12 must be within [0, 1]");
    const double m = std::max(a12, 1.0 - a12);
    constexpr double tol = 1e-9;
    if (m < 0.56 - tol) return EffectMagnitude::Negligible;
    if (m < 0.64 - tol) return EffectMagnitude::Small;
    if (m < 0.71 - tol) return EffectMagnitude::Medium;
    return EffectMagnitude::Large;
}

std::string_view to_string(EffectMagnitude m) {
    switch (m) {
    case EffectMagnitude::Negligible: return "negligible";
    case EffectMagnitude::Small: return "small";
    case EffectMagnitude::Medium: return "medium";
    case EffectMagnitude::Large: return "large";
    }
    return "?";
}

double smallest_attainable_p(std::size_t na, std::size_t nb) {
    if (na == 0 || nb == 0) throw std::invalid_argument("smallest_attainable_p: a group is empty");
    // C(na + nb, na) as a product that stays exact while it is small and
    // finite-and-large (p ~ 0) when it is not.
    double orderings = 1.0;
    const std::size_t k = std::min(na, nb), n = na + nb;
    for (std::size_t i = 1; i <= k; ++i) orderings = orderings * static_cast<double>(n - k + i) / static_cast<double>(i);
    return std::min(1.0, 2.0 / orderings);
}

std::vector<double> holm_adjust(std::span<const double> p_values) {
    for (double p : p_values)
        if (std::isnan(p) || p < 0.0 || p > 1.0)
            throw std::invalid_argument("holm_adjust: p-values must be within [0, 1] (no NaN)");
    const std::size_t m = p_values.size();
    std::vector<std::size_t> order(m);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p_values[a] < p_values[b]; });
    std::vector<double> adjusted(m);
    double running = 0;
    for (std::size_t rank = 0; rank < m; ++rank) {
        const std::size_t i = order[rank];
        running = std::max(running, std::min(1.0, static_cast<double>(m - rank) * p_values[i]));
        adjusted[i] = running;
    }
    return adjusted;
}

} // namespace cic::report::stats
