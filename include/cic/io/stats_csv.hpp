#pragma once
// stats.csv: one row per generation, flushed as it is written so a crashed
// or interrupted run keeps every finished generation.
#include <filesystem>
#include <fstream>
#include <string>

#include "cic/gp/evolution.hpp"

namespace cic::io {

// The column order of stats.csv (plots and sweeps read it by these names).
// mean_depth/max_depth measure forests as GP.forestDepth does (what `limit`
// bounds); the four after wall_seconds give both measures: the sum of the
// trees' depths and the deepest tree. `failed` counts this generation's
// evaluations that failed (physics blow-up, crashed or hung worker).
inline constexpr const char* kStatsColumns =
    "generation,best,mean,median,mean_depth,max_depth,mean_size,max_size,limit,illegal,evaluations,wall_seconds,"
    "mean_depth_sum,max_depth_sum,mean_depth_max,max_depth_max,failed";

// A MAP-Elites run's stats.csv has these columns after kStatsColumns, one row
// per batch: the QD-score (sum of fitness - MapElites.qdOffset over the
// elites), the share of cells filled, the cells filled, and how many of the
// batch's solutions the archive kept. Its `best` is the archive's best,
// `mean` and `median` are over the archive's elites.
inline constexpr const char* kArchiveStatsColumns = "qd_score,coverage,filled,kept";

class StatsWriter {
public:
    // `extra_columns` follow kStatsColumns in the header (kArchiveStatsColumns
    // or none); each write() then gives their cells. Throws std::runtime_error.
    explicit StatsWriter(const std::filesystem::path& path, std::string extra_columns = {});
    // Continues an existing stats.csv (a run resumed in its own folder): keeps the
    // header and the rows up to generation `through`, drops later ones (written
    // after the checkpoint the run resumes from), then appends.
    StatsWriter(const std::filesystem::path& path, int through, std::string extra_columns = {});
    void write(const gp::GenerationRecord& r, const std::string& extra_cells = {});
private:
    std::filesystem::path path_;
    std::ofstream out_;
};

std::string to_csv_row(const gp::GenerationRecord& r);

} // namespace cic::io
