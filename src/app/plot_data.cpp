// The data side of plotting: stats.csv reading, run grouping and per-generation summaries.
#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>

#include "cic/app/plot.hpp"
#include "cic/core/error.hpp"

namespace cic::app {
namespace {

std::vector<std::string> split_csv(const std::string& line) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = line.find(',', start);
        std::string cell = line.substr(start, comma - start);
        while (!cell.empty() && (cell.back() == '\r' || cell.back() == ' ')) cell.pop_back();
        while (!cell.empty() && cell.front() == ' ') cell.erase(cell.begin());
        out.push_back(std::move(cell));
        if (comma == std::string::npos) return out;
        start = comma + 1;
    }
}

double mean_of(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
}

double sd_of(const std::vector<double>& v) {
    if (v.size() < 2) return 0.0;
    const double m = mean_of(v);
    double s = 0;
    for (double x : v) s += (x - m) * (x - m);
    return std::sqrt(s / static_cast<double>(v.size() - 1));
}

} // namespace

std::vector<StatsRow> read_stats_csv(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::ifstream in(path);
    if (!in) throw InputError("cannot read statistics file (is this a run folder?)", file);
    std::string line;
    if (!std::getline(in, line)) throw InputError("empty statistics file (expected a header line)", file, 1);
    const auto header = split_csv(line);
    std::array<std::size_t, kStatsColumns.size()> where{};
    for (std::size_t c = 0; c < kStatsColumns.size(); ++c) {
        const auto it = std::find(header.begin(), header.end(), kStatsColumns[c]);
        if (it == header.end())
            throw InputError(fmt::format("header has no column '{}' (expected {})", kStatsColumns[c],
                                         fmt::join(kStatsColumns, ",")),
                             file, 1);
        where[c] = static_cast<std::size_t>(it - header.begin());
    }
    std::vector<StatsRow> rows;
    int line_no = 1;
    while (std::getline(in, line)) {
        ++line_no;
        if (line.empty() || line == "\r") continue;
        const auto cells = split_csv(line);
        if (cells.size() != header.size())
            throw InputError(fmt::format("{} values, expected {} (one per header column)", cells.size(),
                                         header.size()),
                             file, line_no);
        std::array<double, kStatsColumns.size()> v{};
        for (std::size_t c = 0; c < kStatsColumns.size(); ++c) {
            const std::string& cell = cells[where[c]];
            const auto res = std::from_chars(cell.data(), cell.data() + cell.size(), v[c]);
            if (cell.empty() || res.ec != std::errc() || res.ptr != cell.data() + cell.size())
                throw InputError(fmt::format("column '{}': '{}' is not a number", kStatsColumns[c], cell), file,
                                 line_no);
        }
        if (v[0] != std::floor(v[0]) || v[0] < 0)
            throw InputError(fmt::format("column 'generation': '{}' is not a generation number", cells[where[0]]),
                             file, line_no);
        rows.push_back({static_cast<int>(v[0]), v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11]});
    }
    if (rows.empty()) throw InputError("no data rows after the header", file, line_no);
    return rows;
}

std::string configuration_name(const std::filesystem::path& run_dir) {
    std::filesystem::path p = run_dir;
    if (!p.has_filename()) p = p.parent_path();   // "runs/r1-001/" -> "runs/r1-001"
    std::string name = p.filename().string();
    if (name.empty() || name == "." || name == "..")
        name = std::filesystem::weakly_canonical(p).filename().string();
    static const std::regex numbered("^(.+)-[0-9]+$");
    std::smatch m;
    if (std::regex_match(name, m, numbered)) return m[1].str();
    return name;
}

std::vector<RunGroup> group_runs(const std::vector<std::filesystem::path>& run_dirs) {
    std::vector<RunGroup> groups;
    for (const auto& dir : run_dirs) {
        const std::string label = configuration_name(dir);
        auto it = std::find_if(groups.begin(), groups.end(), [&](const RunGroup& g) { return g.label == label; });
        if (it == groups.end()) {
            groups.push_back({label, {}});
            it = groups.end() - 1;
        }
        it->runs.push_back(dir);
    }
    return groups;
}

std::vector<GenerationSummary> summarise(const std::vector<std::vector<StatsRow>>& runs) {
    std::map<int, std::vector<const StatsRow*>> by_generation;
    for (const auto& run : runs)
        for (const auto& row : run) by_generation[row.generation].push_back(&row);
    std::vector<GenerationSummary> out;
    for (const auto& [generation, rows] : by_generation) {
        auto column = [&](double StatsRow::*field) {
            std::vector<double> v;
            for (const StatsRow* r : rows) v.push_back(r->*field);
            return v;
        };
        GenerationSummary s;
        s.generation = generation;
        s.runs = static_cast<int>(rows.size());
        s.best = mean_of(column(&StatsRow::best));
        s.best_sd = sd_of(column(&StatsRow::best));
        s.mean = mean_of(column(&StatsRow::mean));
        s.mean_sd = sd_of(column(&StatsRow::mean));
        s.mean_depth = mean_of(column(&StatsRow::mean_depth));
        s.max_depth = mean_of(column(&StatsRow::max_depth));
        s.mean_size = mean_of(column(&StatsRow::mean_size));
        s.max_size = mean_of(column(&StatsRow::max_size));
        out.push_back(s);
    }
    return out;
}

} // namespace cic::app
