// pagmo2 behind cic::gait::Search (see search.hpp).
#include "cic/experiments/gait/search.hpp"

#include <cmath>
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

namespace cic::gait {

namespace {

// Exact key of a point: its bits.
std::string key_of(const std::vector<double>& x) {
    std::string k(x.size() * sizeof(double), '\0');
    std::memcpy(k.data(), x.data(), k.size());
    return k;
}

// Shared by the problem copies pagmo makes: what this generation has evaluated,
// and in the first pass, what was asked for.
struct Ledger {
    bool recording = false;
    std::map<std::string, double> known;             // key -> cic fitness
    std::vector<std::vector<double>> asked;          // first pass, in order, without repeats
    const BatchEvaluator* late = nullptr;            // second pass: a point not foreseen
    long evaluated = 0;
};

struct BoxProblem {
    std::size_t n = 1;
    std::shared_ptr<Ledger> ledger = std::make_shared<Ledger>();

    pagmo::vector_double fitness(const pagmo::vector_double& x) const {
        const std::string k = key_of(x);
        if (auto it = ledger->known.find(k); it != ledger->known.end()) return {-it->second};
        if (ledger->recording) {
            ledger->known.emplace(k, 0.0);   // a placeholder, never read in the second pass
            ledger->asked.push_back(x);
            return {0.0};
        }
        if (!ledger->late) throw std::logic_error("gait search: a point was asked for outside a generation");
        const double f = (*ledger->late)({x}).at(0);
        ++ledger->evaluated;
        ledger->known.emplace(k, f);
        return {-f};
    }
    std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
        return {pagmo::vector_double(n, 0.0), pagmo::vector_double(n, 1.0)};
    }
    std::string get_name() const { return "cic gait (unit box)"; }
};

unsigned seed32(std::uint64_t seed, std::uint64_t salt) {
    Rng r(seed ^ (0x9e3779b97f4a7c15ULL * (salt + 1)));
    return static_cast<unsigned>(r.next() >> 32);
}

pagmo::algorithm make_algorithm(Optimizer o, double sigma0, unsigned seed) {
    // Tolerances 0: never stop early (the budget is counted in evaluations);
    // memory on: a call to evolve continues the adaptation of the previous one.
    switch (o) {
    case Optimizer::Cmaes: return pagmo::algorithm{pagmo::cmaes(1u, -1, -1, -1, -1, sigma0, 0.0, 0.0, true, false, seed)};
    case Optimizer::Xnes: return pagmo::algorithm{pagmo::xnes(1u, -1, -1, -1, sigma0, 0.0, 0.0, true, false, seed)};
    case Optimizer::Sade: return pagmo::algorithm{pagmo::sade(1u, 2u, 1u, 0.0, 0.0, true, seed)};
    }
    throw std::invalid_argument("gait search: unknown optimizer");
}

} // namespace

std::string to_string(Optimizer o) {
    switch (o) {
    case Optimizer::Cmaes: return "cmaes";
    case Optimizer::Xnes: return "xnes";
    case Optimizer::Sade: return "sade";
    }
    return "?";
}

struct Search::Impl {
    Optimizer optimizer;
    std::size_t n;
    int lambda;
    std::uint64_t seed;
    BoxProblem problem;
    pagmo::algorithm algorithm;
    pagmo::population pop;
    std::vector<Candidate> current;
    Candidate champion;
    int generation = -1;
    long evaluations = 0;
    std::vector<double> history;

    Impl(Optimizer o, std::size_t dim, int pop_size, double sigma0, std::uint64_t s)
        : optimizer(o), n(dim), lambda(pop_size), seed(s), problem{dim},
          algorithm(make_algorithm(o, sigma0, seed32(s, 1))), pop(pagmo::problem{problem}, 0u, seed32(s, 2)) {}

    // The population pagmo evolves, rebuilt from `current` (no evaluations).
    void rebuild_population() {
        pop = pagmo::population(pagmo::problem{problem}, 0u, seed32(seed, 2));
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
};

Search::Search(Optimizer optimizer, std::size_t dimension, int population, double sigma0, std::uint64_t seed) {
    const int minimum = optimizer == Optimizer::Sade ? 7 : 5;
    if (dimension == 0) throw std::invalid_argument("gait search: no parameters");
    if (population < minimum)
        throw std::invalid_argument("gait search: " + to_string(optimizer) + " needs a population of at least " +
                                    std::to_string(minimum));
    if (!(sigma0 > 0 && sigma0 <= 1)) throw std::invalid_argument("gait search: sigma0 must be in (0, 1]");
    impl_ = std::make_unique<Impl>(optimizer, dimension, population, sigma0, seed);
}

Search::~Search() = default;
Search::Search(Search&&) noexcept = default;
Search& Search::operator=(Search&&) noexcept = default;

void Search::initialise(const BatchEvaluator& evaluate_) {
    Impl& m = *impl_;
    m.history.clear();
    const BatchEvaluator evaluate = m.recording(evaluate_);
    Rng rng(m.seed);
    std::vector<std::vector<double>> xs(static_cast<std::size_t>(m.lambda), std::vector<double>(m.n));
    for (auto& x : xs)
        for (double& v : x) v = rng.uniform(0.0, 1.0);
    const std::vector<double> f = evaluate(xs);
    if (f.size() != xs.size()) throw std::logic_error("gait search: the evaluator returned the wrong count");
    m.current.clear();
    m.champion = {};
    for (std::size_t i = 0; i < xs.size(); ++i) {
        m.current.push_back({xs[i], f[i]});
        m.note(xs[i], f[i]);
    }
    m.evaluations = static_cast<long>(xs.size());
    m.generation = 0;
    m.rebuild_population();
}

void Search::step(const BatchEvaluator& evaluate_) {
    Impl& m = *impl_;
    if (m.generation < 0) throw std::logic_error("gait search: step() before initialise()");
    const BatchEvaluator evaluate = m.recording(evaluate_);
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
    for (const auto& x : ledger.asked) m.note(x, ledger.known.at(key_of(x)));
    m.current.clear();
    for (std::size_t i = 0; i < m.pop.size(); ++i) {
        const auto& x = m.pop.get_x()[i];
        const double f = -m.pop.get_f()[i][0];
        m.current.push_back({x, f});
        m.note(x, f);
    }
    m.evaluations += ledger.evaluated;
    ++m.generation;
    ledger = Ledger{};
}

int Search::generation() const { return impl_->generation; }
long Search::evaluations() const { return impl_->evaluations; }
const std::vector<Candidate>& Search::population() const { return impl_->current; }
const Candidate& Search::champion() const { return impl_->champion; }
int Search::population_size() const { return impl_->lambda; }
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
