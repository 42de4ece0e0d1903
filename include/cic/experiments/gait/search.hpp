#pragma once
// A pagmo2 optimiser (CMA-ES, xNES, SADE, or cic's separable CMA-ES as a pagmo
// algorithm, sep_cmaes.hpp) over the unit box, driven one
// generation at a time so that cic evaluates each generation's candidates as a
// batch, in its worker processes or MPI ranks, and can checkpoint between
// generations.
//
// pagmo's algorithms evaluate candidates one by one through the problem. A
// generation is therefore run twice: first on copies of the optimiser and the
// population, with a problem that only records which points it is asked for;
// those points are evaluated as one batch; then for real, with a problem that
// answers from the batch. The optimiser's random state is copied with it, so
// the second pass asks for the same points. A point the first pass did not
// foresee (an algorithm whose later candidates depend on earlier fitnesses
// within the generation) is evaluated on its own when asked: slower, never
// different. Fitness here is cic's (higher is better); pagmo minimises its
// negation. A checkpoint holds the seed and the fitness history; replay()
// re-runs the optimiser from them, which gives back its exact state.
//
// IPOP restarts (Auger & Hansen, CEC 2005), optional: when a start stagnates
// (RestartRule), the next generation begins a new start of the optimiser from
// fresh uniform points of the unit box with twice the population,
// lambda_r = lambda_0 2^r, and a seed derived from the run seed and r; the
// champion is kept across starts. A decision depends only on the fitness
// history and the candidates, so replay() makes it again.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cic::gait {

enum class Optimizer { Cmaes, Xnes, Sade, Sepcmaes };
std::string to_string(Optimizer o);

struct Candidate {
    std::vector<double> x;
    double fitness = 0.0;
};

enum class Restarts { None, Ipop };
std::string to_string(Restarts r);

// When a start of the optimiser is over (Restarts::Ipop). After each
// generation k of a start (k = 0 is its first batch), with B_k the best
// fitness the start has evaluated so far and P the patience:
//   stagnation  k >= P and B_k - B_{k-P} <= tolerance
//   collapse    k >= 1, tol_x > 0 and every coordinate's standard deviation
//               across the current candidates is below tol_x
// Either one makes the next generation the first of a new start.
struct RestartRule {
    Restarts mode = Restarts::None;
    int patience = 0;          // generations; 0 = 10 + ceil(30 n / lambda_r) (Hansen's TolHistFun window)
    double tolerance = 0.0;    // fitness (metres for the gait)
    double tol_x = 0.0;        // unit-box spread; 0 = no collapse test
};

// Seed of start r of a run seeded `seed`: the seed itself for r = 0, else
// mix64(seed + r * 0x9e3779b97f4a7c15).
std::uint64_t restart_seed(std::uint64_t seed, int r);

// Fitness of each point, in order.
using BatchEvaluator = std::function<std::vector<double>(const std::vector<std::vector<double>>&)>;

class Search {
public:
    // Throws std::invalid_argument: dimension 0, population below pagmo's
    // minimum (cmaes/xnes/sepcmaes 5, sade 7), sigma0 not in (0, 1], ipop restarts for
    // sade, a negative patience, or a tolerance or tol_x negative or not finite.
    Search(Optimizer optimizer, std::size_t dimension, int population, double sigma0, std::uint64_t seed,
           RestartRule restarts = {});
    ~Search();
    Search(Search&&) noexcept;
    Search& operator=(Search&&) noexcept;

    // Where the search starts and samples, set before initialise() (and
    // replay()). `lower`: the box's lower corner, each coordinate's uniform
    // draws in [lower, lower + 1) (empty: the unit box). `x0` (Switch-HybrID's
    // hand-over): the first start's first batch is x0 itself and population - 1
    // points x0 + sigma0 N(0, I) from the seed, so that CMA-ES's mean, the
    // batch's best, starts at or next to x0; restarts draw uniform points as
    // ever (empty: uniform from the start). Throws std::invalid_argument for a
    // size other than the dimension or a non-finite value.
    void set_box(std::vector<double> lower);
    void set_start(std::vector<double> x0);
    const std::vector<double>& start_point() const;

    // Generation 0: `population` uniform points of the unit box, drawn from the
    // seed (or the start around x0, set_start).
    void initialise(const BatchEvaluator& evaluate);
    // One generation of the optimiser, or, when restart_pending(), the first
    // batch of the next start: next_batch_size() uniform points of the unit
    // box drawn from restart_seed(seed, r). Requires initialise() (or replay()).
    // Throws std::overflow_error when a restart's population would pass 10^8.
    void step(const BatchEvaluator& evaluate);

    int generation() const;                        // 0 after initialise
    long evaluations() const;                      // points evaluated so far
    const std::vector<Candidate>& population() const;
    const Candidate& champion() const;             // best point ever evaluated (the first of equals)
    int population_size() const;                   // of the current start: lambda_0 2^restarts()
    // The points step() will evaluate: the doubled population when a restart
    // is pending (for a budget check before the step).
    int next_batch_size() const;
    int restarts() const;                          // starts begun after the first
    bool restart_pending() const;                  // the next step() begins a new start
    // Why the pending restart was decided: the generations since the current
    // start's best last rose by more than the tolerance (>= the patience when
    // it stagnated), and whether its candidates had collapsed instead.
    int stalled_generations() const;
    bool collapsed() const;
    int patience() const;                          // of the current start (the rule's or the default)
    // The generation of each restart's first batch, in order.
    const std::vector<int>& restart_generations() const;
    const RestartRule& restart_rule() const;
    std::size_t dimension() const;
    Optimizer optimizer() const;
    std::uint64_t seed() const;

    // Every fitness the evaluator returned, in order: with the seed, the whole
    // state of the search. (Not pagmo's own archive: pagmo 2.18's CMA-ES
    // serialises a vector it never initialises, so two identical runs would
    // write different bytes.)
    const std::vector<double>& history() const;
    // Rebuilds the search after `generations` steps from a history, evaluating
    // nothing: the optimiser is re-run from the seed and answered from the
    // history in order. Throws std::invalid_argument when the history is too
    // short or too long for that many generations.
    void replay(const std::vector<double>& history, int generations);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace cic::gait
