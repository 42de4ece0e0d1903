#pragma once
// The standard symbolic-regression benchmarks of McDermott et al. 2012
// ("Genetic programming needs better benchmarks", GECCO), with the formulas,
// ranges and samplings that ECJ's ec/app/regression/Benchmarks.java uses:
// koza-1..3, nguyen-1..10, keijzer-1..15, pagie-1, vladislavleva-1..8.
//
// Random samplings U[a, b, n] draw from cic::Rng seeded with
// benchmark_seed(name), so a benchmark's points are the same on every run,
// platform and compiler. ECJ's random points differ from ours (other RNG);
// ranges and counts are the same.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cic/core/rng.hpp"

namespace cic::symreg {

// How the input points of a benchmark are made.
struct Sampling {
    enum class Kind { Random, Grid };
    Kind kind = Kind::Random;
    std::vector<double> min, max;  // per variable
    std::vector<double> step;      // Grid only: spacing per variable
    int points = 0;                // Random only: number of points
    bool same_as_training = false; // test set only: the test set is the training set
};

struct Benchmark {
    std::string name;         // canonical lower-case name, e.g. "keijzer-4"
    int variables = 1;
    std::string formula;      // readable formula, for descriptions and docs
    double (*function)(const double* x) = nullptr;
    Sampling training;
    Sampling test;            // recorded for later use; runs use the training set only
};

// All benchmarks, in the order koza, nguyen, keijzer, pagie, vladislavleva.
const std::vector<Benchmark>& benchmarks();
std::vector<std::string> benchmark_names();
// Case-insensitive; std::nullopt when unknown.
std::optional<Benchmark> find_benchmark(std::string_view name);

// The fixed seed of a benchmark's random points: FNV-1a of its canonical name.
std::uint64_t benchmark_seed(std::string_view canonical_name);

// Input points as columns (columns[v][row]).
// Random: row by row, variable by variable, x = rng.uniform(min, max) (ECJ's order).
// Grid: ECJ's mesh; per variable floor((max - min) / step + 1e-9) + 1 values
// min + j * step (the 1e-9 absorbs rounding such as 0.3 / 0.1 = 2.9999...),
// first variable outermost.
std::vector<std::vector<double>> sample(const Sampling& s, Rng& rng);

} // namespace cic::symreg
