// The data side of plotting: stats.csv and study index.csv reading, run grouping
// and per-generation summaries.
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <map>
#include <regex>
#include <set>
#include <stdexcept>

#include "cic/report/plot.hpp"
#include "cic/report/statistics.hpp"
#include "cic/core/error.hpp"

namespace cic::report {
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

// One line of a CSV file with RFC 4180 quoting ("a,b" and "say ""hi""");
// unquoted cells are trimmed of blanks, a trailing \r is dropped.
std::vector<std::string> split_quoted_csv(std::string line, const std::string& file, int line_no) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::vector<std::string> out;
    std::size_t i = 0;
    for (;;) {
        std::string cell;
        while (i < line.size() && line[i] == ' ') ++i;
        if (i < line.size() && line[i] == '"') {
            ++i;
            for (;;) {
                if (i >= line.size()) throw InputError("a quoted cell has no closing quote", file, line_no);
                if (line[i] == '"') {
                    if (i + 1 < line.size() && line[i + 1] == '"') {
                        cell += '"';
                        i += 2;
                        continue;
                    }
                    ++i;
                    break;
                }
                cell += line[i++];
            }
            while (i < line.size() && line[i] == ' ') ++i;
            if (i < line.size() && line[i] != ',')
                throw InputError("text after a quoted cell's closing quote", file, line_no);
        } else {
            const std::size_t comma = line.find(',', i);
            cell = line.substr(i, comma == std::string::npos ? std::string::npos : comma - i);
            while (!cell.empty() && cell.back() == ' ') cell.pop_back();
            i = comma == std::string::npos ? line.size() : comma;
        }
        out.push_back(std::move(cell));
        if (i >= line.size()) return out;
        ++i;   // the comma
        if (i == line.size()) {   // a trailing comma: one more empty cell
            out.emplace_back();
            return out;
        }
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

// Every run's row of each generation, generations in order.
std::map<int, std::vector<const StatsRow*>> rows_by_generation(const std::vector<std::vector<StatsRow>>& runs) {
    std::map<int, std::vector<const StatsRow*>> by_generation;
    for (const auto& run : runs)
        for (const auto& row : run) by_generation[row.generation].push_back(&row);
    return by_generation;
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
    // Optional columns, read when present.
    auto optional_column = [&](std::string_view name) {
        const auto it = std::find(header.begin(), header.end(), name);
        return it == header.end() ? header.size() : static_cast<std::size_t>(it - header.begin());
    };
    const std::array<std::size_t, 3> optional = {optional_column("best_so_far"), optional_column("qd_score"),
                                                 optional_column("coverage")};
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
            if (cell.empty() || res.ec != std::errc() || res.ptr != cell.data() + cell.size() || !std::isfinite(v[c]))
                throw InputError(fmt::format("column '{}': '{}' is not a finite number", kStatsColumns[c], cell),
                                 file, line_no);
        }
        if (v[0] != std::floor(v[0]) || v[0] < 0)
            throw InputError(fmt::format("column 'generation': '{}' is not a generation number", cells[where[0]]),
                             file, line_no);
        StatsRow row{static_cast<int>(v[0]), v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11]};
        std::array<double*, 3> extra = {&row.best_so_far, &row.qd_score, &row.coverage};
        for (std::size_t c = 0; c < optional.size(); ++c) {
            if (optional[c] == header.size()) continue;
            const std::string& cell = cells[optional[c]];
            double x = 0;
            const auto res = std::from_chars(cell.data(), cell.data() + cell.size(), x);
            if (cell.empty() || res.ec != std::errc() || res.ptr != cell.data() + cell.size() || !std::isfinite(x))
                throw InputError(fmt::format("column '{}': '{}' is not a finite number", header[optional[c]], cell),
                                 file, line_no);
            *extra[c] = x;
        }
        rows.push_back(row);
    }
    if (rows.empty()) throw InputError("no data rows after the header", file, line_no);
    if (optional[0] == header.size()) {   // an older file, or a GP run: the running maximum
        double so_far = rows.front().best;
        for (StatsRow& r : rows) r.best_so_far = so_far = std::max(so_far, r.best);
    }
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

bool is_study_folder(const std::filesystem::path& path) {
    std::error_code ec;
    return std::filesystem::is_directory(path, ec) && std::filesystem::is_regular_file(path / "index.csv", ec);
}

std::vector<std::string> finished_runs_of(const std::vector<std::string>& inputs) {
    std::vector<std::string> out;
    for (const std::string& input : inputs) {
        if (!is_study_folder(input)) {
            out.push_back(input);
            continue;
        }
        const StudyIndex index = read_study_index(input);
        for (const StudyRun& run : index.runs)
            if (run.status == "done") out.push_back(index.run_path(run).string());
    }
    return out;
}

std::vector<std::filesystem::path> runs_missing_from_index(const StudyIndex& index) {
    namespace fs = std::filesystem;
    std::set<fs::path> listed;
    for (const StudyRun& run : index.runs) listed.insert(fs::path(run.run_dir).lexically_normal());
    std::vector<fs::path> out;
    std::error_code ec;
    for (const auto& config : fs::directory_iterator(index.folder / "runs", ec)) {
        if (!config.is_directory(ec)) continue;
        for (const auto& run : fs::directory_iterator(config.path(), ec)) {
            const fs::path rel = fs::path("runs") / config.path().filename() / run.path().filename();
            if (!listed.count(rel) && fs::exists(run.path() / "settings.xml", ec)) out.push_back(index.folder / rel);
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string runs_missing_note(const StudyIndex& index) {
    const auto missing = runs_missing_from_index(index);
    if (missing.empty()) return {};
    std::string list;
    for (std::size_t i = 0; i < missing.size() && i < 5; ++i) list += (i ? ", " : "") + missing[i].string();
    if (missing.size() > 5) list += " and " + std::to_string(missing.size() - 5) + " more";
    return "note: " + std::to_string(missing.size()) + " run folder" + (missing.size() == 1 ? " of " : "s of ") +
           index.folder.string() + (missing.size() == 1 ? " is" : " are") +
           " not in its index.csv (a configuration or seed left the sweep file?) and left out: " + list;
}

StudyIndex read_study_index(const std::filesystem::path& study) {
    const auto file = study / "index.csv";
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError("cannot read the study index (is this a study folder from cic sweep?)", file.string());
    std::ostringstream text;
    text << in.rdbuf();
    return parse_study_index(text.str(), study);
}

StudyIndex parse_study_index(std::string_view text, const std::filesystem::path& study) {
    StudyIndex index;
    index.folder = study;
    index.file = study / "index.csv";
    const std::string file = index.file.string();
    std::istringstream in{std::string(text)};
    std::string line;
    if (!std::getline(in, line)) throw InputError("empty study index (expected a header line)", file, 1);
    const auto header = split_quoted_csv(line, file, 1);
    auto column = [&](std::string_view name) {
        const auto it = std::find(header.begin(), header.end(), name);
        if (it == header.end())
            throw InputError(fmt::format("header has no column '{}' (expected run_dir,config,<varied keys...>,seed,"
                                         "status,final_best,generations,evaluations,wall_seconds)",
                                         name),
                             file, 1);
        if (std::find(it + 1, header.end(), name) != header.end())
            throw InputError(fmt::format("header has column '{}' twice", name), file, 1);
        return static_cast<std::size_t>(it - header.begin());
    };
    const std::size_t c_run = column("run_dir"), c_config = column("config"), c_seed = column("seed"),
                      c_status = column("status"), c_best = column("final_best"),
                      c_generations = column("generations"), c_evaluations = column("evaluations"),
                      c_wall = column("wall_seconds");
    // best_ever came later: an older index has no such column.
    constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);
    const auto best_ever_it = std::find(header.begin(), header.end(), "best_ever");
    const std::size_t c_best_ever =
        best_ever_it == header.end() ? kAbsent : static_cast<std::size_t>(best_ever_it - header.begin());
    if (c_seed < c_config) throw InputError("header has 'seed' before 'config'", file, 1);
    // The varied keys: the other columns between config and seed.
    const std::array<std::size_t, 9> known = {c_run, c_config, c_seed, c_status, c_best,
                                              c_generations, c_evaluations, c_wall, c_best_ever};
    std::vector<std::size_t> varied;
    for (std::size_t c = c_config + 1; c < c_seed; ++c) {
        if (std::find(known.begin(), known.end(), c) != known.end()) continue;
        if (header[c].empty()) throw InputError(fmt::format("header column {} has no name", c + 1), file, 1);
        index.varied_keys.push_back(header[c]);
        varied.push_back(c);
    }

    int line_no = 1;
    while (std::getline(in, line)) {
        ++line_no;
        if (line.empty() || line == "\r") continue;
        const auto cells = split_quoted_csv(line, file, line_no);
        if (cells.size() != header.size())
            throw InputError(fmt::format("{} values, expected {} (one per header column)", cells.size(),
                                         header.size()),
                             file, line_no);
        StudyRun run;
        run.line = line_no;
        run.run_dir = cells[c_run];
        run.config = cells[c_config];
        run.seed = cells[c_seed];
        run.status = cells[c_status];
        if (run.run_dir.empty()) throw InputError("column 'run_dir' is empty", file, line_no);
        if (run.config.empty()) throw InputError("column 'config' is empty", file, line_no);
        if (std::find(kStudyStatuses.begin(), kStudyStatuses.end(), run.status) == kStudyStatuses.end())
            throw InputError(fmt::format("column 'status': '{}' is not one of {}", run.status,
                                         fmt::join(kStudyStatuses, ", ")),
                             file, line_no);
        for (std::size_t c : varied) run.values.push_back(cells[c]);
        auto number = [&](std::size_t c) -> std::optional<double> {
            const std::string& cell = cells[c];
            if (cell.empty()) return std::nullopt;
            double v = 0;
            const auto res = std::from_chars(cell.data(), cell.data() + cell.size(), v);
            // A metric must be finite: inf would print as "inf ± -nan" and rank above every run.
            if (res.ec != std::errc() || res.ptr != cell.data() + cell.size() || !std::isfinite(v))
                throw InputError(fmt::format("column '{}': '{}' is not a finite number", header[c], cell), file,
                                 line_no);
            return v;
        };
        run.final_best = number(c_best);
        run.generations = number(c_generations);
        run.evaluations = number(c_evaluations);
        run.wall_seconds = number(c_wall);
        if (c_best_ever != kAbsent) run.best_ever = number(c_best_ever);
        index.runs.push_back(std::move(run));
    }
    return index;
}

std::vector<StudyGroup> group_study(const StudyIndex& index, bool include_unfinished) {
    std::vector<StudyGroup> groups;
    for (const auto& run : index.runs) {
        auto it = std::find_if(groups.begin(), groups.end(), [&](const StudyGroup& g) { return g.config == run.config; });
        if (it == groups.end()) {
            groups.push_back({run.config, run.values, {}});
            it = groups.end() - 1;
        }
        if (include_unfinished || run.status == "done") it->runs.push_back(&run);
    }
    return groups;
}

std::vector<StatsRow> read_study_run_stats(const StudyIndex& index, const StudyRun& run) {
    const std::filesystem::path file = index.run_path(run) / "stats.csv";
    if (run.status == "done") return read_stats_csv(file);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) return {};
    try {
        return read_stats_csv(file);
    } catch (const InputError&) {
        return {};   // header only, or a line being written right now
    }
}

std::vector<GenerationBands> summarise_bands(const std::vector<std::vector<StatsRow>>& runs, bool median) {
    std::vector<GenerationBands> out;
    // Not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
    for (const auto& by_generation : rows_by_generation(runs)) {
        const int generation = by_generation.first;
        const auto& rows = by_generation.second;
        auto band = [&](double StatsRow::*field) {
            std::vector<double> v;
            for (const StatsRow* r : rows)
                if (!std::isnan(r->*field)) v.push_back(r->*field);
            if (v.empty()) return Band{NAN, NAN, NAN};
            const stats::Descriptive d = stats::describe(v);
            return median ? Band{d.median, d.q1, d.q3} : Band{d.mean, d.mean - d.sd, d.mean + d.sd};
        };
        GenerationBands g;
        g.generation = generation;
        g.runs = static_cast<int>(rows.size());
        g.best = band(&StatsRow::best);
        g.mean = band(&StatsRow::mean);
        g.mean_depth = band(&StatsRow::mean_depth);
        g.max_depth = band(&StatsRow::max_depth);
        g.best_so_far = band(&StatsRow::best_so_far);
        g.qd_score = band(&StatsRow::qd_score);
        g.coverage = band(&StatsRow::coverage);
        out.push_back(g);
    }
    return out;
}

std::vector<EvaluationBand> summarise_by_evaluations(const std::vector<std::vector<StatsRow>>& runs, bool median,
                                                     int points) {
    if (points < 1) throw std::invalid_argument("summarise_by_evaluations: points must be at least 1");
    double most = 0;
    for (const auto& run : runs)
        if (!run.empty()) most = std::max(most, run.back().evaluations);
    std::vector<EvaluationBand> out;
    if (most <= 0) return out;
    // Per run: the next row to take in and the best so far (NaN until a finite best).
    std::vector<std::size_t> next(runs.size(), 0);
    std::vector<double> best(runs.size(), NAN);
    for (int k = 1; k <= points; ++k) {
        const double e = most * k / points;
        std::vector<double> v;
        for (std::size_t r = 0; r < runs.size(); ++r) {
            while (next[r] < runs[r].size() && runs[r][next[r]].evaluations <= e) {
                const double b = runs[r][next[r]++].best;
                if (!std::isnan(b) && !(b <= best[r])) best[r] = b;   // also replaces the first NaN
            }
            if (!std::isnan(best[r])) v.push_back(best[r]);
        }
        if (v.empty()) continue;
        const stats::Descriptive d = stats::describe(v);
        out.push_back({e, static_cast<int>(v.size()),
                       median ? Band{d.median, d.q1, d.q3} : Band{d.mean, d.mean - d.sd, d.mean + d.sd}});
    }
    return out;
}

std::vector<GenerationSummary> summarise(const std::vector<std::vector<StatsRow>>& runs) {
    std::vector<GenerationSummary> out;
    // Not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
    for (const auto& by_generation : rows_by_generation(runs)) {
        const int generation = by_generation.first;
        const auto& rows = by_generation.second;
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
        s.best_so_far = mean_of(column(&StatsRow::best_so_far));
        s.best_so_far_sd = sd_of(column(&StatsRow::best_so_far));
        s.qd_score = mean_of(column(&StatsRow::qd_score));
        s.qd_score_sd = sd_of(column(&StatsRow::qd_score));
        s.coverage = mean_of(column(&StatsRow::coverage));
        s.coverage_sd = sd_of(column(&StatsRow::coverage));
        out.push_back(s);
    }
    return out;
}

} // namespace cic::report
