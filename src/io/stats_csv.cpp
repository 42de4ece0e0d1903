#include "cic/io/stats_csv.hpp"

#include <cstdio>
#include <stdexcept>

#include "cic/io/xml.hpp"

namespace cic::io {

std::string to_csv_row(const gp::GenerationRecord& r) {
    char buf[512];
    std::snprintf(buf, sizeof buf, "%d,%.17g,%.17g,%.17g,%.6g,%d,%.6g,%zu,%d,%d,%ld,%.3f,%.6g,%d,%.6g,%d,%d", r.generation,
                  r.best, r.mean, r.median, r.mean_depth, r.max_depth, r.mean_size, r.max_size, r.limit, r.illegal,
                  r.evaluations, r.wall_seconds, r.mean_depth_sum, r.max_depth_sum, r.mean_depth_max,
                  r.max_depth_max, r.failed);
    return buf;
}

namespace {
std::string header_of(const std::string& extra_columns) {
    return std::string(kStatsColumns) + (extra_columns.empty() ? "" : "," + extra_columns);
}
} // namespace

StatsWriter::StatsWriter(const std::filesystem::path& path, std::string extra_columns) : path_(path), out_(path) {
    if (!out_) throw std::runtime_error(path.string() + ": cannot write statistics file");
    out_ << header_of(extra_columns) << '\n' << std::flush;
}

StatsWriter::StatsWriter(const std::filesystem::path& path, int through, std::string extra_columns) : path_(path) {
    std::string kept;
    {
        std::ifstream in(path);
        std::string line;
        if (std::getline(in, line)) kept = line + '\n';
        while (std::getline(in, line)) {
            int generation = -1;
            if (std::sscanf(line.c_str(), "%d,", &generation) == 1 && generation <= through) kept += line + '\n';
        }
    }
    if (kept.empty()) kept = header_of(extra_columns) + '\n';
    xml::write_file_atomically(path, kept);
    out_.open(path, std::ios::app);
    if (!out_) throw std::runtime_error(path.string() + ": cannot write statistics file");
}

void StatsWriter::write(const gp::GenerationRecord& r, const std::string& extra_cells) {
    out_ << to_csv_row(r) << (extra_cells.empty() ? "" : ",") << extra_cells << '\n' << std::flush;
    if (!out_) throw std::runtime_error(path_.string() + ": write failed (disk full?)");
}

} // namespace cic::io
