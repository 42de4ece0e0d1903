// One self-contained HTML page for a run or a study (html_report.hpp).
#include "cic/study/html_report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdlib.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <fstream>
#include <optional>
#include <set>

#include "cic/core/error.hpp"
#include "cic/io/experiment_types.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/io/xml.hpp"
#include "cic/report/archive_plot.hpp"
#include "cic/report/gait_assessment.hpp"
#include "cic/report/path_plot.hpp"
#include "cic/report/plot.hpp"
#include "cic/report/replay.hpp"
#include "cic/run/provenance.hpp"
#include "cic/study/compare_table.hpp"

namespace cic::study {

namespace fs = std::filesystem;

std::string base64(const std::string& bytes) {
    static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const auto b = [&](std::size_t k) { return k < bytes.size() ? static_cast<unsigned char>(bytes[k]) : 0u; };
        const unsigned v = b(i) << 16 | b(i + 1) << 8 | b(i + 2);
        out += kDigits[v >> 18 & 63];
        out += kDigits[v >> 12 & 63];
        out += i + 1 < bytes.size() ? kDigits[v >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? kDigits[v & 63] : '=';
    }
    return out;
}

std::string html_escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&#39;"; break;
        default: out += c;
        }
    }
    return out;
}

namespace {

// A scratch folder for the figures, removed afterwards.
class Scratch {
public:
    Scratch() {
        std::string templ = (fs::temp_directory_path() / "cic-report-XXXXXX").string();
        if (!mkdtemp(templ.data())) throw std::runtime_error("report: cannot create a temporary folder");
        path_ = templ;
    }
    ~Scratch() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;
    fs::path operator/(const std::string& name) const { return path_ / name; }

private:
    fs::path path_;
};

// A figure file as an <img> whose source is the file itself (a data URI).
std::string image(const fs::path& file, const std::string& alt) {
    const std::string type = file.extension() == ".svg" ? "image/svg+xml" : "image/png";
    return fmt::format("<img alt=\"{}\" src=\"data:{};base64,{}\">\n", html_escape(alt), type, base64(io::xml::read_file(file)));
}

std::string note(const std::string& text) { return "<p class=\"note\">" + html_escape(text) + "</p>\n"; }

// A figure made by `draw` into `file`, or a note saying why there is none.
template <class Draw>
std::string figure(const fs::path& file, const std::string& alt, Draw draw) {
    try {
        draw(file);
        return image(file, alt);
    } catch (const std::exception& e) {
        return note(alt + ": not drawn (" + e.what() + ")");
    }
}

std::string table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
    std::string html = "<table>\n<tr>";
    for (const auto& h : header) html += "<th>" + html_escape(h) + "</th>";
    html += "</tr>\n";
    for (const auto& row : rows) {
        html += "<tr>";
        for (const auto& cell : row) html += "<td>" + html_escape(cell) + "</td>";
        html += "</tr>\n";
    }
    return html + "</table>\n";
}

std::string num(double v, int digits = 4) { return std::isfinite(v) ? fmt::format("{:.{}g}", v, digits) : "-"; }
std::string num(const std::optional<double>& v) { return v ? num(*v) : "-"; }

// run.log's head: the build, host, start and command line (run/provenance.hpp).
std::string provenance_of(const fs::path& run) {
    std::ifstream in(run / "run.log");
    std::string line, head;
    static const std::array<std::string_view, 7> kHead = {"commit:", "built:",   "libraries:", "host:",
                                                          "started:", "command:", "settings:"};
    for (int n = 0; std::getline(in, line); ++n) {
        const bool known = n == 0 ? line.rfind("cic ", 0) == 0 && line.find(':') == std::string::npos
                                  : std::any_of(kHead.begin(), kHead.end(),
                                                [&](std::string_view p) { return line.rfind(p, 0) == 0; });
        if (!known) break;
        head += line + '\n';
    }
    return head.empty() ? "(no run.log header: a run made before cic recorded its provenance)\n" : head;
}

struct Shown {
    std::string name;   // the configuration, or the run folder's name
    fs::path run;
    std::string seed;
};

// The strip's times: four instants over the replay, the first just after the start.
std::vector<double> strip_times(double duration) {
    return {0.05 * duration, duration / 3, 2 * duration / 3, duration};
}

std::string walk_section(const Shown& shown, const ReportOptions& options, const Scratch& scratch, std::size_t k,
                         std::vector<report::CentrePath>& paths) {
    std::string html = fmt::format("<h3>{}{}</h3>\n", html_escape(shown.name),
                                   shown.seed.empty() ? "" : html_escape(" (best run: seed " + shown.seed + ")"));
    std::vector<report::ReplayItem> items;
    try {
        items = report::replay(shown.run.string(), "best", 1, 10.0, true);
    } catch (const std::exception& e) {
        return html + note(std::string("no replay: ") + e.what());
    }
    const report::ReplayItem& item = items.front();
    html += "<p>" + html_escape(item.label) + fmt::format(", fitness {:.4f}", item.replayed_fitness) + "</p>\n";
    // The strip.
    const double duration = item.recording.times.empty() ? 0.0 : item.recording.times.back() - item.recording.times.front();
    if (!options.strip) {
        html += note("No strip: " + options.no_strip_reason + ".");
    } else {
        const fs::path png = scratch / fmt::format("strip{}.png", k);
        const std::string why = options.strip(shown.run, strip_times(duration), png);
        html += why.empty() && fs::exists(png) ? image(png, "strip of " + shown.name)
                                               : note("No strip: " + (why.empty() ? "the viewer wrote none" : why));
    }
    // The path and the verdict.
    paths.push_back(report::centre_path(item, shown.name));
    html += "<div class=\"row\">\n";
    html += figure(scratch / fmt::format("path{}.svg", k), "path of " + shown.name,
                   [&](const fs::path& f) {
                       report::PlotOptions o;
                       o.gnuplot = options.gnuplot;
                       o.width = 560;
                       o.title = shown.name + ": the centre's path from above";
                       report::plot_paths({paths.back()}, f, o);
                   });
    try {
        const report::GaitAssessment a = report::assess_gait(item);
        std::string duty;
        for (std::size_t f = 0; f < a.foot_names.size(); ++f)
            duty += fmt::format("{}{} {:.2f}", f ? ", " : "", a.foot_names[f], a.duty_factors[f]);
        html += "<div><p class=\"verdict\">cic assess: <b>" + html_escape(a.verdict) + "</b></p>\n";
        html += table({"measure", "value"},
                      {{"distance along the preferred axis [m]", num(a.distance)},
                       {"elevation gained [m]", num(a.elevation)},
                       {"fitness (eq. 7.1 alone)", num(a.raw_fitness)},
                       {"dominant command frequency [Hz]", num(a.dominant_hz, 3)},
                       {"centre height, mean / lowest [m]", num(a.mean_height, 3) + " / " + num(a.min_height, 3)},
                       {"flipped", a.flipped ? "yes" : "no"},
                       {"duty factor per foot", duty.empty() ? "-" : duty}});
        html += "</div>\n";
    } catch (const std::exception& e) {
        html += note(std::string("no assessment: ") + e.what());
    }
    html += "</div>\n";
    return html;
}

constexpr const char* kStyle = R"(<style>
body { font-family: sans-serif; max-width: 1250px; margin: 1em auto; padding: 0 1em; color: #222; }
h1 { font-size: 1.5em; } h2 { border-bottom: 1px solid #ccc; margin-top: 1.6em; } h3 { margin-bottom: 0.3em; }
table { border-collapse: collapse; margin: 0.5em 0; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 2px 8px; text-align: left; }
th { background: #f0f0f0; }
pre { background: #f6f6f6; padding: 0.6em; overflow-x: auto; font-size: 0.85em; }
img { max-width: 100%; height: auto; border: 1px solid #eee; }
.note { color: #8a5a00; font-style: italic; }
.row { display: flex; flex-wrap: wrap; gap: 1.5em; align-items: flex-start; }
.row img { max-width: 560px; }
.verdict { font-size: 1.1em; }
</style>
)";

} // namespace

std::string report_html(const fs::path& folder, const ReportOptions& options) {
    const bool study = report::is_study_folder(folder);
    if (!study && !(fs::is_regular_file(folder / "settings.xml") && fs::is_regular_file(folder / "stats.csv")))
        throw InputError("not a run folder (settings.xml and stats.csv) or a study folder (index.csv)", folder.string());
    fs::path p = folder;
    if (!p.has_filename()) p = p.parent_path();
    const std::string name = fs::weakly_canonical(p).filename().string();
    Scratch scratch;

    std::vector<Shown> shown;
    std::optional<report::StudyIndex> index;
    if (study) {
        index = report::read_study_index(folder);
        for (const report::StudyGroup& g : report::group_study(*index, options.include_unfinished))
            if (const report::StudyRun* r = report::best_run_of(g)) shown.push_back({g.config, index->run_path(*r), r->seed});
        if (shown.empty())
            throw InputError("the study has no done run to report (--include-unfinished also shows the others)",
                             index->file.string());
    } else {
        shown.push_back({name, folder, ""});
    }

    std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    html += fmt::format("<title>cic report: {}</title>\n", html_escape(name));
    html += kStyle;
    html += "</head>\n<body>\n";
    html += fmt::format("<h1>cic report: {} ({})</h1>\n", html_escape(name), study ? "study" : "run");
    html += fmt::format("<p>Made by cic {} on {} at {} from <code>{}</code>. One file: every figure is inside it.</p>\n",
                        html_escape(run::build_label()), html_escape(run::host_name()),
                        html_escape(run::iso_utc(std::chrono::system_clock::now())),
                        html_escape(fs::weakly_canonical(folder).string()));

    // Provenance.
    html += "<h2>Provenance</h2>\n";
    if (study) {
        std::set<std::string> commits;
        for (const report::StudyRun& r : index->runs) {
            const std::string c = run::recorded_commit(index->run_path(r));
            if (!c.empty()) commits.insert(c);
        }
        html += "<p>Commits that made the study's runs: " +
                html_escape(commits.empty() ? "not recorded" : fmt::format("{}", fmt::join(commits, ", "))) +
                ".</p>\n";
        html += "<p>The run.log header of " + html_escape(shown.front().run.filename().string()) + ":</p>\n";
    }
    html += "<pre>" + html_escape(provenance_of(shown.front().run)) + "</pre>\n";

    // The compare table.
    if (study) {
        html += "<h2>Comparison</h2>\n";
        try {
            CompareRequest request;
            request.metric = options.metric;
            request.include_unfinished = options.include_unfinished;
            const CompareData d = compare_data(folder, request);
            std::vector<std::vector<std::string>> rows;
            for (const auto& c : d.configs)
                rows.push_back({c.config, std::to_string(c.n), num(c.median), num(c.q1) + " - " + num(c.q3),
                                num(c.q3 - c.q1), num(c.mean) + " +- " + num(c.sd)});
            html += fmt::format("<p>Metric: <code>{}</code> of each run (index.csv).</p>\n", html_escape(d.metric));
            html += table({"configuration", "n", "median", "Q1 - Q3", "IQR", "mean +- sd"}, rows);
            rows.clear();
            for (const auto& r : d.pairs)
                rows.push_back(r.tested ? std::vector<std::string>{r.a, r.b, num(r.p, 3), num(r.p_holm, 3),
                                                                   fmt::format("{:.2f} [{:.2f}, {:.2f}]", r.a12,
                                                                               r.a12_low, r.a12_high),
                                                                   r.effect, r.verdict}
                                        : std::vector<std::string>{r.a, r.b, "-", "-", "-", "-", r.verdict});
            if (!rows.empty()) {
                html += fmt::format("<p>Two-sided Mann-Whitney U per pair, p adjusted by Holm over the pairs (alpha "
                                    "{}); A12 = P(a run of A beats one of B) with its 95% interval (DeLong).</p>\n",
                                    d.alpha);
                html += table({"A", "B", "p", "p (Holm)", "A12 [95% interval]", "effect", "verdict"}, rows);
            }
        } catch (const std::exception& e) {
            html += note(std::string("no comparison: ") + e.what());
        }
    }

    // The curves.
    html += "<h2>Curves</h2>\n";
    html += figure(scratch / "curves.svg", "curves", [&](const fs::path& f) {
        if (study) {
            report::StudyPlotOptions o;
            o.gnuplot = options.gnuplot;
            o.include_unfinished = options.include_unfinished;
            o.median = true;
            report::plot_study(folder, f, o);
        } else {
            report::PlotOptions o;
            o.gnuplot = options.gnuplot;
            report::plot_runs({folder}, f, o);
        }
    });

    // Each configuration's best gait.
    bool robots = true;
    try {
        robots = io::family_of(io::read_settings(shown.front().run / "settings.xml")) != io::ExperimentFamily::Symreg;
    } catch (const std::exception&) {
    }
    if (robots) {
        html += "<h2>The best gait of each configuration</h2>\n";
        html += "<p>Frames of the replay with a camera fixed on the world, the centre's path so far on the ground "
                "(green ring: the start); its path from above; and <code>cic assess</code>'s verdict.</p>\n";
        std::vector<report::CentrePath> paths;
        for (std::size_t k = 0; k < shown.size(); ++k) html += walk_section(shown[k], options, scratch, k, paths);
        if (paths.size() > 1)
            html += "<h3>All paths</h3>\n" + figure(scratch / "paths.svg", "all paths", [&](const fs::path& f) {
                        report::PlotOptions o;
                        o.gnuplot = options.gnuplot;
                        report::plot_paths(paths, f, o);
                    });
    }

    // MAP-Elites archives.
    std::string heatmaps;
    for (std::size_t k = 0; k < shown.size(); ++k) {
        if (!report::is_archive_run(shown[k].run)) continue;
        heatmaps += "<h3>" + html_escape(shown[k].name) + "</h3>\n" +
                    figure(scratch / fmt::format("archive{}.svg", k), "archive of " + shown[k].name,
                           [&](const fs::path& f) {
                               report::ArchivePlotOptions o;
                               o.gnuplot = options.gnuplot;
                               report::plot_archive(shown[k].run, f, o);
                           });
    }
    if (!heatmaps.empty()) html += "<h2>MAP-Elites archives</h2>\n" + heatmaps;

    // The runs.
    html += "<h2>Runs</h2>\n";
    std::vector<std::vector<std::string>> rows;
    if (study) {
        for (const report::StudyRun& r : index->runs)
            rows.push_back({r.run_dir, r.config, r.seed, r.status, num(r.final_best), num(r.best_ever),
                            num(r.generations), num(r.evaluations), num(r.wall_seconds)});
        html += table({"run", "configuration", "seed", "status", "final best", "best ever", "generations",
                       "evaluations", "wall seconds"},
                      rows);
    } else {
        const auto stats = report::read_stats_csv(folder / "stats.csv");
        const report::StatsRow& last = stats.back();
        rows.push_back({name, std::to_string(last.generation), num(last.best), num(last.best_so_far),
                        num(last.evaluations), num(last.wall_seconds)});
        html += table({"run", std::string("last ") + report::x_axis_name(report::search_kind_of(folder)), "its best", "best so far",
                       "evaluations", "wall seconds"},
                      rows);
        // A run still going has no summary yet; one that cannot be read is an error, not a blank.
        if (fs::exists(folder / "summary.txt"))
            html += "<pre>" + html_escape(io::xml::read_file(folder / "summary.txt")) + "</pre>\n";
    }
    html += "</body>\n</html>\n";
    return html;
}

} // namespace cic::study
