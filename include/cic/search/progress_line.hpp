#pragma once
// What the console shows of one finished generation or batch (run/progress.hpp prints it).

namespace cic::search {

struct ProgressLine {
    int generation = 0;               // the generation just finished, from 0 (as stats.csv)
    int max_generations = 0;          // 0 = unknown
    double evaluations_per_second = 0;
    double best = 0;
    double mean = 0;
    int limit = 0;                    // dynamic depth limit (0 = none)
    double eta_seconds = -1;          // < 0 = unknown
    // A MAP-Elites run (>= 0): the share of the archive filled. The line then
    // counts batches and shows the coverage instead of a depth limit.
    double coverage = -1;
};

} // namespace cic::search
