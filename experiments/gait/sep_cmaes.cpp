// Separable CMA-ES (see sep_cmaes.hpp); the update of Hansen's tutorial
// ("The CMA Evolution Strategy: A Tutorial", 2016) with C diagonal and the
// rank-one and rank-mu rates of Ros & Hansen 2008.
#include "sep_cmaes.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include <pagmo/problem.hpp>

namespace cic::gait::detail {

SepCmaes::SepCmaes(double sigma0, unsigned seed) : sigma0_(sigma0) {
    if (!(sigma0 > 0 && sigma0 <= 1)) throw std::invalid_argument("sep-cmaes: sigma0 must be in (0, 1]");
    state_.rng = Rng(seed);
}

pagmo::population SepCmaes::evolve(pagmo::population pop) const {
    const pagmo::problem& prob = pop.get_problem();
    if (prob.get_nf() != 1 || prob.get_nc() != 0)
        throw std::invalid_argument("sep-cmaes: the problem must be single-objective and unconstrained");
    const std::size_t lambda = pop.size();
    if (lambda < 5) throw std::invalid_argument("sep-cmaes: needs a population of at least 5");
    const std::size_t n = prob.get_nx();
    const double dn = static_cast<double>(n);
    State& s = state_;
    if (!s.started || s.mean.size() != n) {
        s.mean.assign(n, 0.0);
        for (const auto& x : pop.get_x())
            for (std::size_t j = 0; j < n; ++j) s.mean[j] += x[j] / static_cast<double>(lambda);
        s.variance.assign(n, 1.0);
        s.ps.assign(n, 0.0);
        s.pc.assign(n, 0.0);
        s.sigma = sigma0_;
        s.generation = 0;
        s.started = true;
    }

    // Strategy parameters (Hansen's defaults, the covariance rates scaled for sep).
    const std::size_t mu = lambda / 2;
    std::vector<double> w(mu);
    for (std::size_t i = 0; i < mu; ++i) w[i] = std::log(static_cast<double>(mu) + 0.5) - std::log(static_cast<double>(i + 1));
    const double wsum = std::accumulate(w.begin(), w.end(), 0.0);
    double w2 = 0;
    for (double& v : w) {
        v /= wsum;
        w2 += v * v;
    }
    const double mueff = 1.0 / w2;
    const double cs = (mueff + 2) / (dn + mueff + 5);
    const double damps = 1 + 2 * std::max(0.0, std::sqrt((mueff - 1) / (dn + 1)) - 1) + cs;
    const double cc = (4 + mueff / dn) / (dn + 4 + 2 * mueff / dn);
    const double c1_full = 2 / ((dn + 1.3) * (dn + 1.3) + mueff);
    const double cmu_full = std::min(1 - c1_full, 2 * (mueff - 2 + 1 / mueff) / ((dn + 2) * (dn + 2) + mueff));
    const double c1 = std::min(1.0, c1_full * (dn + 2) / 3);
    const double cmu = std::min(1 - c1, cmu_full * (dn + 2) / 3);
    const double chi_n = std::sqrt(dn) * (1 - 1 / (4 * dn) + 1 / (21 * dn * dn));

    // Sample every candidate first, then evaluate them in order.
    std::vector<std::vector<double>> x(lambda, std::vector<double>(n));
    for (auto& xk : x)
        for (std::size_t j = 0; j < n; ++j) xk[j] = s.mean[j] + s.sigma * std::sqrt(s.variance[j]) * s.rng.normal();
    std::vector<double> f(lambda);
    for (std::size_t k = 0; k < lambda; ++k) {
        const pagmo::vector_double fk = prob.fitness(x[k]);
        f[k] = fk[0];
        pop.set_xf(k, x[k], fk);
    }
    std::vector<std::size_t> order(lambda);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return f[a] < f[b]; });

    const std::vector<double> old = s.mean;
    for (std::size_t j = 0; j < n; ++j) {
        double m = 0;
        for (std::size_t i = 0; i < mu; ++i) m += w[i] * x[order[i]][j];
        s.mean[j] = m;
    }
    double ps_norm2 = 0;
    const double ps_rate = std::sqrt(cs * (2 - cs) * mueff);
    for (std::size_t j = 0; j < n; ++j) {
        const double yw = (s.mean[j] - old[j]) / s.sigma;
        s.ps[j] = (1 - cs) * s.ps[j] + ps_rate * yw / std::sqrt(s.variance[j]);
        ps_norm2 += s.ps[j] * s.ps[j];
    }
    const double ps_norm = std::sqrt(ps_norm2);
    const double fade = 1 - std::pow(1 - cs, 2.0 * static_cast<double>(s.generation + 1));
    const bool hsig = ps_norm / std::sqrt(fade) / chi_n < 1.4 + 2 / (dn + 1);
    const double pc_rate = std::sqrt(cc * (2 - cc) * mueff);
    for (std::size_t j = 0; j < n; ++j) {
        const double yw = (s.mean[j] - old[j]) / s.sigma;
        s.pc[j] = (1 - cc) * s.pc[j] + (hsig ? pc_rate * yw : 0.0);
        double rank_mu = 0;
        for (std::size_t i = 0; i < mu; ++i) {
            const double y = (x[order[i]][j] - old[j]) / s.sigma;
            rank_mu += w[i] * y * y;
        }
        const double rank_one = s.pc[j] * s.pc[j] + (hsig ? 0.0 : cc * (2 - cc) * s.variance[j]);
        s.variance[j] = (1 - c1 - cmu) * s.variance[j] + c1 * rank_one + cmu * rank_mu;
    }
    s.sigma *= std::exp((cs / damps) * (ps_norm / chi_n - 1));
    ++s.generation;
    return pop;
}

} // namespace cic::gait::detail
