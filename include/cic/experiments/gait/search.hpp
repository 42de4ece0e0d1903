#pragma once
// A pagmo2 optimiser (CMA-ES, xNES or SADE) over the unit box, driven one
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
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cic::gait {

enum class Optimizer { Cmaes, Xnes, Sade };
std::string to_string(Optimizer o);

struct Candidate {
    std::vector<double> x;
    double fitness = 0.0;
};

// Fitness of each point, in order.
using BatchEvaluator = std::function<std::vector<double>(const std::vector<std::vector<double>>&)>;

class Search {
public:
    // Throws std::invalid_argument: dimension 0, population below pagmo's
    // minimum (cmaes/xnes 5, sade 7), sigma0 not in (0, 1].
    Search(Optimizer optimizer, std::size_t dimension, int population, double sigma0, std::uint64_t seed);
    ~Search();
    Search(Search&&) noexcept;
    Search& operator=(Search&&) noexcept;

    // Generation 0: `population` uniform points of the unit box, drawn from the seed.
    void initialise(const BatchEvaluator& evaluate);
    // One generation of the optimiser. Requires initialise() (or replay()).
    void step(const BatchEvaluator& evaluate);

    int generation() const;                        // 0 after initialise
    long evaluations() const;                      // points evaluated so far
    const std::vector<Candidate>& population() const;
    const Candidate& champion() const;             // best point ever evaluated (the first of equals)
    int population_size() const;
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
