#pragma once
// The tables of `cic compare STUDY`: per configuration n, mean +- sd, median,
// IQR and the time to a threshold; per pair Mann-Whitney U, A12 and Holm's
// correction (the statistics: cic/report/statistics.hpp, docs/statistics.md).
#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace cic::study {

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

// The same comparison as numbers, for pages that lay it out themselves (cic
// report): per configuration the metric's summary, per pair the tests with
// A12's 95% interval (stats::a12_interval). Configurations without values
// have n = 0; untested pairs have tested = false.
struct CompareConfigRow {
    std::string config;
    std::size_t n = 0;
    double median = 0, q1 = 0, q3 = 0, mean = 0, sd = 0;
};
struct ComparePairRow {
    std::string a, b;
    bool tested = false;
    double p = 1, p_holm = 1, a12 = 0.5, a12_low = 0.5, a12_high = 0.5;
    std::string effect, verdict;
    bool significant = false;
};
struct CompareData {
    std::string metric;
    double alpha = 0.05;
    std::vector<CompareConfigRow> configs;
    std::vector<ComparePairRow> pairs;
};
CompareData compare_data(const std::filesystem::path& study, const CompareRequest& request);

// Reads STUDY/index.csv and the runs' stats.csv. Throws cic::InputError for a
// bad request, a folder without an index, or no usable run.
CompareTables compare_study(const std::filesystem::path& study, const CompareRequest& request);

} // namespace cic::study
