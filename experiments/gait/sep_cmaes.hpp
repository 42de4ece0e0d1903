#pragma once
// Separable CMA-ES (Ros & Hansen, "A simple modification in CMA-ES achieving
// linear time and space complexity", PPSN X, 2008) as a pagmo2 user-defined
// algorithm, for the gait search (search.cpp) on robots whose gaits have
// hundreds of numbers. pagmo2's own cmaes adapts the full n x n covariance; at
// n = 289 (96 hinges) its learning rate, about 2 / n^2, leaves it almost
// isotropic within a 2,500-evaluation budget. Sep-CMA-ES keeps only the
// diagonal and raises the learning rates by (n + 2) / 3.
//
// One evolve() is one generation of lambda = pop.size() candidates, sampled
// from cic's Rng (the same bits on every platform), evaluated through the
// population's problem in order and written back over the population
// (non-elitist, like pagmo's cmaes). The state is kept between calls, so that
// successive calls continue one adaptation (pagmo's "memory"); it starts from
// the mean of the population it is first given (a start's uniform points: the
// centre of the box, give or take) with step sigma0 on every coordinate. Points are not forced into the bounds: the gait encoding clamps
// or reflects them, as it does for pagmo's cmaes.
#include <string>
#include <vector>

#include <pagmo/population.hpp>

#include "cic/core/rng.hpp"

namespace cic::gait::detail {

class SepCmaes {
public:
    SepCmaes() = default;
    // Throws std::invalid_argument when sigma0 is not in (0, 1].
    SepCmaes(double sigma0, unsigned seed);

    // Throws std::invalid_argument for a population below 5 or a problem that
    // is not single-objective and unconstrained.
    pagmo::population evolve(pagmo::population pop) const;
    std::string get_name() const { return "sep-CMA-ES (cic)"; }

private:
    struct State {
        bool started = false;
        long generation = 0;
        double sigma = 0.0;
        std::vector<double> mean, variance, ps, pc;   // variance: the diagonal of C
        Rng rng;
    };
    double sigma0_ = 0.5;
    mutable State state_;   // evolve() is const in pagmo's interface
};

} // namespace cic::gait::detail
