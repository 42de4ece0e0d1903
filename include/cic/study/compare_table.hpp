#pragma once
// The tables of `cic compare STUDY`: per configuration n, mean +- sd, median,
// IQR and the time to a threshold; per pair Mann-Whitney U, A12 and Holm's
// correction (the statistics: cic/report/statistics.hpp, docs/statistics.md).
#include <array>
#include <filesystem>
#include <string>
#include <string_view>

namespace cic::app {

// The index.csv columns a comparison can summarise and test.
inline constexpr std::array<std::string_view, 5> kCompareMetrics = {"final_best", "best_ever", "generations",
                                                                    "evaluations", "wall_seconds"};

struct CompareRequest {
    double threshold = 0;
    bool has_threshold = false;       // report when each run's best first reached threshold
    std::string metric = "final_best";
    double alpha = 0.05;              // for the Holm-adjusted p-values
    bool include_unfinished = false;  // also runs whose status is not done
};

struct CompareTables {
    std::string markdown;      // what `cic compare` prints
    std::string configs_csv;   // PREFIX-configs.csv
    std::string pairs_csv;     // PREFIX-pairs.csv
};

// Reads STUDY/index.csv and the runs' stats.csv. Throws cic::InputError for a
// bad request, a folder without an index, or no usable run.
CompareTables compare_study(const std::filesystem::path& study, const CompareRequest& request);

} // namespace cic::app
