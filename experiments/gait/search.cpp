// pagmo2 behind cic::gait::Search (see search.hpp).
#include "cic/experiments/gait/search.hpp"

#include <cmath>
#include <algorithm>
#include <cstring>
#include <map>
#include <sstream>
#include <stdexcept>

#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/sade.hpp>
#include <pagmo/algorithms/xnes.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>

#include "cic/core/rng.hpp"
#include "pagmo_box.hpp"
#include "sep_cmaes.hpp"

namespace cic::gait {

namespace {

using detail::BoxProblem;
using detail::key_of;
using detail::Ledger;
using detail::seed32;

pagmo::algorithm make_algorithm(Optimizer o, double sigma0, unsigned seed) {
    // Tolerances 0: never stop early (the budget is counted in evaluations);
    // memory on: a call to evolve continues the adaptation of the previous one.
    switch (o) {
    case Optimizer::Cmaes: return pagmo::algorithm{pagmo::cmaes(1u, -1, -1, -1, -1, sigma0, 0.0, 0.0, true, false, seed)};
    case Optimizer::Xnes: return pagmo::algorithm{pagmo::xnes(1u, -1, -1, -1, sigma0, 0.0, 0.0, true, false, seed)};
    case Optimizer::Sade: return pagmo::algorithm{pagmo::sade(1u, 2u, 1u, 0.0, 0.0, true, seed)};
    case Optimizer::Sepcmaes: return pagmo::algorithm{detail::SepCmaes(sigma0, seed)};
    }
    throw std::invalid_argument("gait search: unknown optimizer");
}

} // namespace

std::string to_string(Restarts r) { return r == Restarts::Ipop ? "ipop" : "none"; }

std::uint64_t restart_seed(std::uint64_t seed, int r) {
    if (r == 0) return seed;
    return mix64(seed + 0x9e3779b97f4a7c15ULL * static_cast<std::uint64_t>(r));
}

std::string to_string(Optimizer o) {
    switch (o) {
    case Optimizer::Cmaes: return "cmaes";
    case Optimizer::Xnes: return "xnes";
    case Optimizer::Sade: return "sade";
    case Optimizer::Sepcmaes: return "sepcmaes";
    }
    return "?";
}

struct Search::Impl {
    Optimizer optimizer;
    std::size_t n;
    int lambda0;                  // the first start's population
    int lambda;                   // the current start's: lambda0 2^restart
    double sigma0;
    std::uint64_t seed;
    RestartRule rule;
    BoxProblem problem;
    pagmo::algorithm algorithm;
    pagmo::population pop;
    std::vector<Candidate> current;
    Candidate champion;
    int generation = -1;
    long evaluations = 0;
    std::vector<double> history;
    // The current start: its number, and B_0, B_1, ...: the best fitness it
    // has evaluated after each of its generations.
    int restart = 0;
    std::vector<double> start_best;
    std::vector<int> restart_generations;
    bool pending = false;         // the next step begins start restart + 1
    int stalled = 0;
    bool collapsed = false;
    std::vector<double> lower;    // the box's lower corner; empty = 0
    std::vector<double> x0;       // the first start's centre (set_start); empty = uniform

    Impl(Optimizer o, std::size_t dim, int pop_size, double sigma, std::uint64_t s, RestartRule r)
        : optimizer(o), n(dim), lambda0(pop_size), lambda(pop_size), sigma0(sigma), seed(s), rule(r), problem{dim},
          algorithm(make_algorithm(o, sigma, seed32(s, 1))), pop(pagmo::problem{problem}, 0u, seed32(s, 2)) {}

    std::uint64_t start_seed() const { return restart_seed(seed, restart); }

    // The population pagmo evolves, rebuilt from `current` (no evaluations).
    void rebuild_population() {
        pop = pagmo::population(pagmo::problem{problem}, 0u, seed32(start_seed(), 2));
        for (const Candidate& c : current) pop.push_back(c.x, {-c.fitness});
    }

    // The evaluator, with every fitness it returns appended to the history.
    BatchEvaluator recording(const BatchEvaluator& evaluate) {
        return [this, &evaluate](const std::vector<std::vector<double>>& xs) {
            std::vector<double> f = evaluate(xs);
            if (f.size() != xs.size()) throw std::logic_error("gait search: the evaluator returned the wrong count");
            history.insert(history.end(), f.begin(), f.end());
            return f;
        };
    }

    void note(const std::vector<double>& x, double f) {
        if (champion.x.empty() || f > champion.fitness) champion = {x, f};
    }

    // The first batch of the current start: lambda uniform points of the unit
    // box from the start's seed, and a fresh optimiser.
    void begin_start(const BatchEvaluator& evaluate) {
        const std::uint64_t s = start_seed();
        Rng rng(s);
        std::vector<std::vector<double>> xs(static_cast<std::size_t>(lambda), std::vector<double>(n));
        if (restart == 0 && !x0.empty()) {
            xs[0] = x0;
            for (std::size_t i = 1; i < xs.size(); ++i)
                for (std::size_t d = 0; d < n; ++d) xs[i][d] = x0[d] + sigma0 * rng.normal();
        } else if (lower.empty()) {
            for (auto& x : xs)
                for (double& v : x) v = rng.uniform(0.0, 1.0);
        } else {
            for (auto& x : xs)
                for (std::size_t d = 0; d < n; ++d) x[d] = rng.uniform(lower[d], lower[d] + 1.0);
        }
        const std::vector<double> f = evaluate(xs);
        if (f.size() != xs.size()) throw std::logic_error("gait search: the evaluator returned the wrong count");
        current.clear();
        double best = f.empty() ? 0.0 : f.front();
        for (std::size_t i = 0; i < xs.size(); ++i) {
            current.push_back({xs[i], f[i]});
            note(xs[i], f[i]);
            best = std::max(best, f[i]);
        }
        evaluations += static_cast<long>(xs.size());
        algorithm = make_algorithm(optimizer, sigma0, seed32(s, 1));
        rebuild_population();
        start_best.assign(1, best);
    }

    int patience() const {
        if (rule.patience > 0) return rule.patience;
        return 10 + static_cast<int>((30 * n + static_cast<std::size_t>(lambda) - 1) / static_cast<std::size_t>(lambda));
    }

    // After each generation: is the current start over?
    void decide() {
        pending = false;
        stalled = 0;
        collapsed = false;
        if (rule.mode == Restarts::None) return;
        const int k = static_cast<int>(start_best.size()) - 1;
        const int p = patience();
        const double now = start_best.back();
        // !(a > b), so that a start whose every fitness is -inf stagnates too.
        if (k >= p && !(now - start_best[static_cast<std::size_t>(k - p)] > rule.tolerance)) {
            int j = k;
            while (j > 0 && !(now - start_best[static_cast<std::size_t>(j - 1)] > rule.tolerance)) --j;
            pending = true;
            stalled = k - j;
            return;
        }
        if (k >= 1 && rule.tol_x > 0 && current.size() >= 2) {
            const double m = static_cast<double>(current.size());
            for (std::size_t d = 0; d < n; ++d) {
                double mean = 0;
                for (const Candidate& c : current) mean += c.x[d];
                mean /= m;
                double ss = 0;
                for (const Candidate& c : current) ss += (c.x[d] - mean) * (c.x[d] - mean);
                if (!(std::sqrt(ss / (m - 1)) < rule.tol_x)) return;
            }
            pending = true;
            collapsed = true;
            int j = k;
            while (j > 0 && !(now - start_best[static_cast<std::size_t>(j - 1)] > rule.tolerance)) --j;
            stalled = k - j;
        }
    }
};

Search::Search(Optimizer optimizer, std::size_t dimension, int population, double sigma0, std::uint64_t seed,
               RestartRule restarts) {
    const int minimum = optimizer == Optimizer::Sade ? 7 : 5;
    if (dimension == 0) throw std::invalid_argument("gait search: no parameters");
    if (population < minimum)
        throw std::invalid_argument("gait search: " + to_string(optimizer) + " needs a population of at least " +
                                    std::to_string(minimum));
    if (!(sigma0 > 0 && sigma0 <= 1)) throw std::invalid_argument("gait search: sigma0 must be in (0, 1]");
    if (restarts.mode == Restarts::Ipop && optimizer == Optimizer::Sade)
        throw std::invalid_argument("gait search: ipop restarts need cmaes or xnes, not sade");
    if (restarts.patience < 0) throw std::invalid_argument("gait search: a negative restart patience");
    if (!(restarts.tolerance >= 0) || !std::isfinite(restarts.tolerance))
        throw std::invalid_argument("gait search: the restart tolerance must be finite and >= 0");
    if (!(restarts.tol_x >= 0) || !std::isfinite(restarts.tol_x))
        throw std::invalid_argument("gait search: the restart tol_x must be finite and >= 0");
    impl_ = std::make_unique<Impl>(optimizer, dimension, population, sigma0, seed, restarts);
}

Search::~Search() = default;
Search::Search(Search&&) noexcept = default;
Search& Search::operator=(Search&&) noexcept = default;

namespace {

void check_point(const std::vector<double>& x, std::size_t n, const char* what) {
    if (x.size() != n)
        throw std::invalid_argument(std::string("gait search: ") + what + " of " + std::to_string(x.size()) +
                                    " coordinates for " + std::to_string(n) + " parameters");
    for (double v : x)
        if (!std::isfinite(v)) throw std::invalid_argument(std::string("gait search: ") + what + " is not finite");
}

} // namespace

void Search::set_box(std::vector<double> lower) {
    check_point(lower, impl_->n, "a box corner");
    impl_->lower = std::move(lower);
}

void Search::set_start(std::vector<double> x0) {
    check_point(x0, impl_->n, "a start point");
    impl_->x0 = std::move(x0);
}

const std::vector<double>& Search::start_point() const { return impl_->x0; }

void Search::initialise(const BatchEvaluator& evaluate_) {
    Impl& m = *impl_;
    m.history.clear();
    const BatchEvaluator evaluate = m.recording(evaluate_);
    m.champion = {};
    m.evaluations = 0;
    m.restart = 0;
    m.lambda = m.lambda0;
    m.restart_generations.clear();
    m.begin_start(evaluate);
    m.generation = 0;
    m.decide();
}

void Search::step(const BatchEvaluator& evaluate_) {
    Impl& m = *impl_;
    if (m.generation < 0) throw std::logic_error("gait search: step() before initialise()");
    const BatchEvaluator evaluate = m.recording(evaluate_);
    if (m.pending) {
        if (m.lambda > 50000000) throw std::overflow_error("gait search: a restart's population would pass 10^8");
        ++m.restart;
        m.lambda *= 2;
        m.begin_start(evaluate);
        ++m.generation;
        m.restart_generations.push_back(m.generation);
        m.decide();
        return;
    }
    Ledger& ledger = *m.problem.ledger;
    ledger = Ledger{};
    // Pass 1, on copies: which points will this generation ask for?
    ledger.recording = true;
    {
        pagmo::algorithm algorithm = m.algorithm;
        pagmo::population pop = m.pop;
        algorithm.evolve(pop);
    }
    ledger.recording = false;
    ledger.known.clear();
    if (!ledger.asked.empty()) {
        const std::vector<double> f = evaluate(ledger.asked);
        if (f.size() != ledger.asked.size()) throw std::logic_error("gait search: the evaluator returned the wrong count");
        for (std::size_t i = 0; i < f.size(); ++i) ledger.known.emplace(key_of(ledger.asked[i]), f[i]);
        ledger.evaluated = static_cast<long>(f.size());
    }
    // Pass 2, for real.
    ledger.late = &evaluate;
    m.pop = m.algorithm.evolve(m.pop);
    ledger.late = nullptr;
    // Every point evaluated this generation may be the champion, in the order asked.
    double best = m.start_best.back();
    for (const auto& x : ledger.asked) {
        const double f = ledger.known.at(key_of(x));
        m.note(x, f);
        best = std::max(best, f);
    }
    m.current.clear();
    for (std::size_t i = 0; i < m.pop.size(); ++i) {
        const auto& x = m.pop.get_x()[i];
        const double f = -m.pop.get_f()[i][0];
        m.current.push_back({x, f});
        m.note(x, f);
        best = std::max(best, f);
    }
    m.evaluations += ledger.evaluated;
    ++m.generation;
    ledger = Ledger{};
    m.start_best.push_back(best);
    m.decide();
}

int Search::generation() const { return impl_->generation; }
long Search::evaluations() const { return impl_->evaluations; }
const std::vector<Candidate>& Search::population() const { return impl_->current; }
const Candidate& Search::champion() const { return impl_->champion; }
int Search::population_size() const { return impl_->lambda; }
int Search::next_batch_size() const { return impl_->pending ? 2 * impl_->lambda : impl_->lambda; }
int Search::restarts() const { return impl_->restart; }
bool Search::restart_pending() const { return impl_->pending; }
int Search::stalled_generations() const { return impl_->stalled; }
bool Search::collapsed() const { return impl_->collapsed; }
int Search::patience() const { return impl_->patience(); }
const RestartRule& Search::restart_rule() const { return impl_->rule; }
const std::vector<int>& Search::restart_generations() const { return impl_->restart_generations; }
std::size_t Search::dimension() const { return impl_->n; }
Optimizer Search::optimizer() const { return impl_->optimizer; }
std::uint64_t Search::seed() const { return impl_->seed; }

const std::vector<double>& Search::history() const { return impl_->history; }

void Search::replay(const std::vector<double>& history, int generations) {
    if (generations < 0) throw std::invalid_argument("gait search: a negative generation count");
    std::size_t next = 0;
    const BatchEvaluator from_history = [&](const std::vector<std::vector<double>>& xs) {
        if (history.size() - next < xs.size())
            throw std::invalid_argument("gait search: the history ends before generation " + std::to_string(generations));
        std::vector<double> f(history.begin() + static_cast<std::ptrdiff_t>(next),
                              history.begin() + static_cast<std::ptrdiff_t>(next + xs.size()));
        next += xs.size();
        return f;
    };
    initialise(from_history);
    for (int g = 0; g < generations; ++g) step(from_history);
    if (next != history.size())
        throw std::invalid_argument("gait search: the history holds " + std::to_string(history.size() - next) +
                                    " fitness values past generation " + std::to_string(generations));
}

} // namespace cic::gait
