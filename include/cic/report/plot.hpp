#pragma once
// Plots with gnuplot in place of the thesis's MATLAB: run statistics per
// generation (thesis figs 7.4-7.7) and network traces (figs 7.8-7.10).
// Output format follows the file extension: .svg or .png.
#include <array>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cic::report {

// The header of RUN_DIR/stats.csv, in this order (the run writes it, plots read it).
inline constexpr std::array<std::string_view, 12> kStatsColumns = {
    "generation", "best", "mean", "median", "mean_depth", "max_depth",
    "mean_size",  "max_size", "limit", "illegal", "evaluations", "wall_seconds"};

struct StatsRow {
    int generation = 0;
    double best = 0, mean = 0, median = 0;
    double mean_depth = 0, max_depth = 0, mean_size = 0, max_size = 0;
    double limit = 0, illegal = 0, evaluations = 0, wall_seconds = 0;
    // Optional columns: the best of every generation up to this one (the
    // column, or the running maximum of `best` where a file has none), and a
    // MAP-Elites run's QD-score and coverage (NaN where a file has none).
    double best_so_far = std::numeric_limits<double>::quiet_NaN();
    double qd_score = std::numeric_limits<double>::quiet_NaN();
    double coverage = std::numeric_limits<double>::quiet_NaN();
};

// Reads a stats.csv. Columns are found by name in the header (kStatsColumns
// must be there; best_so_far, qd_score and coverage are read when present;
// other columns are ignored). Throws cic::InputError naming the file and line: missing file, a
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
    double best_so_far = 0, best_so_far_sd = 0, qd_score = 0, qd_score_sd = 0, coverage = 0, coverage_sd = 0;
};
std::vector<GenerationSummary> summarise(const std::vector<std::vector<StatsRow>>& runs);

// A study folder (written by `cic sweep`): STUDY/index.csv lists one run per line,
//   run_dir,config,<varied key columns...>,seed,status,final_best,generations,evaluations,wall_seconds[,best_ever]
// with run_dir relative to STUDY and status one of pending, running, done,
// interrupted, failed. Cells holding a comma or a double quote are quoted
// ("..." with "" for a quote).
inline constexpr std::array<std::string_view, 5> kStudyStatuses = {"pending", "running", "done", "interrupted",
                                                                   "failed"};
struct StudyRun {
    std::string run_dir;                  // as written: relative to the study folder
    std::string config;
    std::vector<std::string> values;      // of the varied keys, in index order
    std::string seed;
    std::string status;
    std::optional<double> final_best;     // empty cells stay empty
    std::optional<double> best_ever;      // empty too in an index written before the column existed
    std::optional<double> generations, evaluations, wall_seconds;
    int line = 0;                         // line in index.csv
};
struct StudyIndex {
    std::filesystem::path folder;
    std::filesystem::path file;           // folder / "index.csv"
    std::vector<std::string> varied_keys; // the columns between config and seed
    std::vector<StudyRun> runs;           // in file order
    std::filesystem::path run_path(const StudyRun& run) const { return folder / run.run_dir; }
};
// A folder that holds an index.csv.
bool is_study_folder(const std::filesystem::path& path);
// The inputs with each study folder replaced by its finished runs (status
// done), as assess and transfer take them; other inputs as they are.
std::vector<std::string> finished_runs_of(const std::vector<std::string>& inputs);
// Reads STUDY/index.csv; columns are found by name. Throws cic::InputError with
// the file and line: missing file or column, a wrong number of cells, an unknown
// status, a non-numeric number cell, an empty run_dir or config.
StudyIndex read_study_index(const std::filesystem::path& study);
// The same on the text of an index.csv (`study` names the folder; messages name study/index.csv).
StudyIndex parse_study_index(std::string_view text, const std::filesystem::path& study);
// Run folders STUDY/runs/CONFIG/RUN holding a run (settings.xml) that index.csv
// does not list: runs of a configuration or seed an edited sweep file dropped.
// Readers of the study leave them out; plot and export say so (runs_missing_note).
std::vector<std::filesystem::path> runs_missing_from_index(const StudyIndex& index);
// "note: N run folder(s) of STUDY are not in its index.csv ...: A, B", or "" when none.
std::string runs_missing_note(const StudyIndex& index);

// Configurations of a study in order of first appearance, with their runs
// (status done only unless include_unfinished).
struct StudyGroup {
    std::string config;
    std::vector<std::string> values;      // the first run's varied key values
    std::vector<const StudyRun*> runs;
};
std::vector<StudyGroup> group_study(const StudyIndex& index, bool include_unfinished);

// The stats.csv rows of one run of a study. A done run's stats.csv must read
// (read_stats_csv's errors); for any other status a missing, header-only or
// half-written file gives no rows.
std::vector<StatsRow> read_study_run_stats(const StudyIndex& index, const StudyRun& run);

// Per generation over runs: a centre with a band for best and mean fitness and
// mean and max depth. Mean with mean +- sd (sd with n-1; 0 for one run), or with
// `median` the median with Q1..Q3 (numpy's linear quantiles, statistics.hpp).
// Generations that only some runs reached use those runs.
struct Band {
    double centre = 0, low = 0, high = 0;
};
struct GenerationBands {
    int generation = 0;
    int runs = 0;
    Band best, mean, mean_depth, max_depth;
    Band best_so_far, qd_score, coverage;   // NaN where the runs' files have no such column
};
std::vector<GenerationBands> summarise_bands(const std::vector<std::vector<StatsRow>>& runs, bool median);

// Best fitness found so far against evaluations used, over the runs of one
// configuration: at `points` evenly spaced evaluation counts up to the most any
// of the runs used (the `evaluations` column is cumulative), the centre and band
// (as summarise_bands) of each run's best so far. A run counts from its first
// row on and keeps its last value after it stopped, since a best found within
// the budget stays found. Runs of a method that counts evaluations per
// generation differently (HyperGP: the population; CMA-ES: lambda) so line up
// at equal cost. Throws std::invalid_argument for points < 1.
struct EvaluationBand {
    double evaluations = 0;
    int runs = 0;
    Band best_so_far;
};
std::vector<EvaluationBand> summarise_by_evaluations(const std::vector<std::vector<StatsRow>>& runs, bool median,
                                                     int points = 200);

struct PlotOptions {
    std::string gnuplot = "gnuplot";   // executable, looked up on PATH
    std::string title;                 // figure title; empty = none
    int width = 0, height = 0;         // pixels; 0 = a size that suits the plot
};

// What a run searched with, which decides the panels that mean something for
// it (from its settings.xml; GP when that cannot be read).
enum class SearchKind { GP, Gait, MapElites };
SearchKind search_kind_of(const std::filesystem::path& run_dir);
// The x axis's name for a search: "generation", or "batch" for MAP-Elites.
std::string x_axis_name(SearchKind kind);
// A gait run's IPOP restarts: the generation each restart's first batch was
// (from its population.xml); empty without restarts or a readable checkpoint.
std::vector<int> restart_generations(const std::filesystem::path& run_dir);

// Panels that fit the runs' search (the first run's; every run must have the
// same), one curve per configuration with a legend, each a mean over runs with
// a +-1 sd band when a group has several runs. GP: best fitness, mean fitness,
// mean and max depth, mean and max size. Gait (CMA-ES and the others): best
// so far with each generation's best, IPOP restarts marked, and the
// generation's mean. MAP-Elites: QD-score, coverage, the best elite and the
// elites' mean fitness, per batch. Throws cic::InputError for bad
// input (names the stats.csv and line), std::runtime_error when gnuplot fails
// (its message is included).
void plot_runs(const std::vector<std::filesystem::path>& run_dirs, const std::filesystem::path& out_file,
               const PlotOptions& options = {});

// A study: one colour per configuration, panels as plot_runs's for the
// study's search (GP: best fitness, mean fitness, max depth, mean depth),
// each a centre line with a band (see summarise_bands). Runs are those group_study(index, include_unfinished) keeps
// that have a stats.csv with rows; a configuration without any is left out.
// Throws cic::InputError when the study has no run to plot.
struct StudyPlotOptions : PlotOptions {
    bool median = false;               // median and IQR instead of mean +- sd
    bool include_unfinished = false;   // also runs whose status is not done
};
void plot_study(const std::filesystem::path& study, const std::filesystem::path& out_file,
                const StudyPlotOptions& options = {});

// Several studies on one panel: best fitness so far against evaluations (see
// summarise_by_evaluations), one colour per (study, configuration), e.g. HyperGP
// against CMA-ES at the same budget. With `configs`, only those configurations
// (by their config name), and every study must have each of them. Labels are
// "STUDY: CONFIG", or "STUDY" when one configuration per study is shown.
// Throws cic::InputError naming the study for a missing configuration or a
// study without a done run (or any run with statistics, with include_unfinished).
struct EvaluationPlotOptions : StudyPlotOptions {
    std::vector<std::string> configs;  // empty = every configuration
};
void plot_studies_by_evaluations(const std::vector<std::filesystem::path>& studies,
                                 const std::filesystem::path& out_file, const EvaluationPlotOptions& options = {});

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

} // namespace cic::report
