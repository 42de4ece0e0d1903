#pragma once
// Plots with gnuplot in place of the thesis's MATLAB: run statistics per
// generation (thesis figs 7.4-7.7) and network traces (figs 7.8-7.10).
// Output format follows the file extension: .svg or .png.
#include <array>
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace cic::app {

// The header of RUN_DIR/stats.csv, in this order (the run writes it, plots read it).
inline constexpr std::array<std::string_view, 12> kStatsColumns = {
    "generation", "best", "mean", "median", "mean_depth", "max_depth",
    "mean_size",  "max_size", "limit", "illegal", "evaluations", "wall_seconds"};

struct StatsRow {
    int generation = 0;
    double best = 0, mean = 0, median = 0;
    double mean_depth = 0, max_depth = 0, mean_size = 0, max_size = 0;
    double limit = 0, illegal = 0, evaluations = 0, wall_seconds = 0;
};

// Reads a stats.csv. Columns are found by name in the header (extra columns are
// ignored). Throws cic::InputError naming the file and line: missing file, a
// missing column, a non-numeric cell, a wrong number of cells, no data rows.
std::vector<StatsRow> read_stats_csv(const std::filesystem::path& path);

// Runs of one configuration. Run folders are grouped by their folder name with
// the numbered suffix the runner adds removed ("r1_mid-003" -> "r1_mid"), so
// repeated runs of one settings file fall into one group. Groups keep the order
// in which their first folder was given.
struct RunGroup {
    std::string label;
    std::vector<std::filesystem::path> runs;
};
std::string configuration_name(const std::filesystem::path& run_dir);
std::vector<RunGroup> group_runs(const std::vector<std::filesystem::path>& run_dirs);

// Per generation over the runs of a group: mean and sample standard deviation
// (0 with one run) of each statistic; generations present in fewer runs (a run
// that stopped early) use the runs that reached them.
struct GenerationSummary {
    int generation = 0;
    int runs = 0;
    double best = 0, best_sd = 0, mean = 0, mean_sd = 0;
    double mean_depth = 0, max_depth = 0, mean_size = 0, max_size = 0;
};
std::vector<GenerationSummary> summarise(const std::vector<std::vector<StatsRow>>& runs);

struct PlotOptions {
    std::string gnuplot = "gnuplot";   // executable, looked up on PATH
    std::string title;                 // figure title; empty = none
    int width = 0, height = 0;         // pixels; 0 = a size that suits the plot
};

// Four panels: best fitness, mean fitness (each mean over runs with a +-1 sd
// band when a group has several runs), mean and max depth, mean and max size;
// one curve per configuration with a legend. Throws cic::InputError for bad
// input (names the stats.csv and line), std::runtime_error when gnuplot fails
// (its message is included).
void plot_runs(const std::vector<std::filesystem::path>& run_dirs, const std::filesystem::path& out_file,
               const PlotOptions& options = {});

struct TracePlotOptions : PlotOptions {
    std::vector<std::string> joints;                                // empty = all joints
    double from = -std::numeric_limits<double>::infinity();        // s
    double to = std::numeric_limits<double>::infinity();           // s
};

// One panel per joint: raw network output, averaged command and actual angle
// over time, from a trace CSV (see trace_csv.hpp).
void plot_trace(const std::filesystem::path& trace_csv, const std::filesystem::path& out_file,
                const TracePlotOptions& options = {});

// Runs `gnuplot script_file`; throws std::runtime_error with gnuplot's error
// output when it cannot be started or exits non-zero.
void run_gnuplot(const std::string& gnuplot, const std::filesystem::path& script_file);

} // namespace cic::app
