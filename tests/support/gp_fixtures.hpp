#pragma once
// A small symbolic-regression set-up for tests of the evolution loop: a pure
// fitness that counts its calls, and a GP configuration small enough to run
// many generations in milliseconds.
#include <cmath>
#include <span>

#include "cic/gp/evolution.hpp"
#include "cic/tree/eval.hpp"

namespace cic::testing {

// A pure fitness: -sum |f(x) - (x^2 + x)| on 11 points in [-1, 1]. Counts its calls.
class QuadraticEvaluator final : public gp::Evaluator {
public:
    void evaluate(std::span<const gp::IndividualPtr> todo) override {
        for (const auto& ind : todo) {
            double err = 0;
            for (int i = 0; i <= 10; ++i) {
                const double xs[1] = {-1.0 + 0.2 * i};
                err += std::abs(tree::evaluate_point(ind->genotype[0], xs) - (xs[0] * xs[0] + xs[0]));
            }
            ind->fitness = std::isfinite(err) ? -err : -1e30;
            ind->evaluated = true;
            ++calls;
        }
    }
    long calls = 0;
};

// 30 individuals of x0 over {add, sub, mul} and the constant 1, depth 1..4, tournament 3.
inline gp::GpConfig small_gp_config() {
    gp::GpConfig c;
    c.population_size = 30;
    c.expected_tree_size = 8;
    c.min_init_depth = 1;
    c.max_init_depth = 4;
    c.primitives = {{tree::Op::Add, tree::Op::Sub, tree::Op::Mul}, {}, 1, {1.0}};
    c.tournament_size = 3;
    return c;
}

} // namespace cic::testing
