#pragma once
// The symbolic-regression problem (thesis 6.2.1): build the reference points
// from the settings, and score a genotype against them.
#include <string>
#include <vector>

#include "cic/tree/tree.hpp"
#include "cic/experiments/symreg/benchmarks.hpp"
#include "cic/experiments/symreg/config.hpp"
#include "cic/experiments/symreg/dataset.hpp"
#include "cic/experiments/symreg/expression.hpp"

namespace cic::symreg {

// Builds the training data from the config, first match wins:
//  1. data_file set: CSV (see load_csv); a relative path is resolved against base_dir
//     (the folder of the settings file).
//  2. target names a benchmark (case-insensitive, see benchmark_names()): its formula
//     on its own training points when benchmark_sampling, else on `samples`
//     equidistant points in [range_min, range_max] per variable.
//  3. otherwise target is an infix expression (see expression.hpp) sampled on
//     `samples` equidistant points in [range_min, range_max] per variable.
// Equidistant: x_i = rmin + i (rmax - rmin) / (n - 1), i = 0..n-1, both ends included
// (n = 1 gives rmin alone); with 2+ variables the full n^v grid, x0 outermost.
// Throws cic::InputError: an unknown name that looks like a benchmark (lists the
// known ones), a bad expression (column and what was expected), CSV errors
// (file:line), samples < 1, range_min > range_max, non-finite hit_tolerance < 0,
// more than 10^7 points, or a target that is not finite at some point.
Dataset make_dataset(const SymregConfig& cfg, const std::string& base_dir);

// n equidistant values in [lo, hi], both ends included (exactly lo and hi).
std::vector<double> equidistant(int n, double lo, double hi);

struct Score {
    double fitness = 0.0;  // -sum_k |y_k - r_k| (thesis eq. 6.1-6.2); higher is better
    int hits = 0;          // points with |y_k - r_k| <= hit_tolerance
    bool success = false;  // every point is a hit
};

// The fitness of a failed result: the error sum is NaN, infinite or >= 1e30.
// Finite, so sorting and statistics never meet NaN, and every failure ties.
inline constexpr double failed_fitness = -1e30;

// Scores tree 0 of the genotype (a symreg genotype has one tree; any further
// trees are ignored) on every row of `data`. If the error sum is not finite or
// reaches 1e30 (cic's tree operators clamp outputs to +-DBL_MAX, so a wild tree
// gives a huge but finite sum), fitness = failed_fitness and success = false;
// hits still counts the points within tolerance. `scratch` holds the outputs (resized as needed)
// so repeated calls do not allocate. Throws std::invalid_argument for an empty
// genotype or a tree that reads a variable the data does not have.
Score score(const tree::Forest& genotype, const Dataset& data, double hit_tolerance,
            std::vector<double>& scratch);

} // namespace cic::symreg
