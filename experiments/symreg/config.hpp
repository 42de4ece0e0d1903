#pragma once
// Settings of the symbolic-regression experiment (thesis 6.2.1).
#include <string>

namespace cic::symreg {

struct SymregConfig {
    std::string target = "koza-1";   // benchmark name, or an expression over x (x0), y (x1) ...
    std::string data_file;           // CSV with header; last column is the target (overrides target)
    int samples = 20;                // n equidistant points (when not the benchmark's own)
    double range_min = -1.0;
    double range_max = 1.0;
    bool benchmark_sampling = true;  // use the named benchmark's own training set
    double hit_tolerance = 0.01;     // a point is a hit when |error| <= this
};

} // namespace cic::symreg
