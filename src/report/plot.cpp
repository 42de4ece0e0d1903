// gnuplot scripts for run statistics and network traces.
#include "cic/report/plot.hpp"

#include "cic/io/experiment_types.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/settings_io.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "cic/report/trace_csv.hpp"
#include "gnuplot_support.hpp"
#include "cic/core/error.hpp"

namespace cic::report {
namespace {

using detail::check_output_folder;
using detail::quote;
using detail::render;
using detail::ScratchDir;
using detail::terminal_for;
using detail::write_file;

namespace fs = std::filesystem;

constexpr std::array<const char*, 8> kColours = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                                 "#9467bd", "#8c564b", "#e377c2", "#17becf"};

// Whole generations on the x axis: gnuplot's own step goes below 1 on short runs.
std::string generation_ticks(const std::string& data_file) {
    return fmt::format("stats {} using 1 nooutput\nif (STATS_max - STATS_min <= 10) {{ set xtics 1 }}\n"
                       "set format x '%.0f'\n",
                       data_file);
}

// The fitness axis with its unit: eq. 7.1 in metres for the robot experiments.
std::string fitness_label(const fs::path& run_dir, const std::string& what = "fitness") {
    try {
        if (io::family_of(io::read_settings(run_dir / "settings.xml")) == io::ExperimentFamily::Symreg)
            return what + " (-sum |error|)";
        return what + " [m] (eq. 7.1)";
    } catch (const std::exception&) {
        return what;   // no readable settings: no unit to claim
    }
}

// A curve with a band per series: centre column `col`, band columns col+1 (low)
// and col+2 (high); the band only where a series has several runs.
struct BandSeries {
    std::string label;
    std::size_t runs = 0;
    std::string data;   // gnuplot-quoted data file
};
std::string band_plot_command(const std::vector<BandSeries>& series, int col) {
    std::vector<std::string> items;
    for (std::size_t k = 0; k < series.size(); ++k) {
        const std::string colour = fmt::format("rgb '{}'", kColours[k % kColours.size()]);
        const std::string label =
            fmt::format("{} ({} run{})", series[k].label, series[k].runs, series[k].runs == 1 ? "" : "s");
        if (series[k].runs > 1)
            items.push_back(fmt::format("{} using 1:{}:{} with filledcurves fs transparent solid 0.18 noborder "
                                        "lc {} notitle",
                                        series[k].data, col + 1, col + 2, colour));
        items.push_back(
            fmt::format("{} using 1:{} with lines lw 2 lc {} title {}", series[k].data, col, colour, quote(label)));
    }
    return fmt::format("plot {}\n", fmt::join(items, ", \\\n  "));
}

// The done runs of a study configuration (or every run with statistics).
std::vector<std::vector<StatsRow>> stats_of(const StudyIndex& index, const StudyGroup& group) {
    std::vector<std::vector<StatsRow>> runs;
    for (const StudyRun* run : group.runs) {
        auto rows = read_study_run_stats(index, *run);
        if (!rows.empty()) runs.push_back(std::move(rows));
    }
    return runs;
}

InputError nothing_to_plot(const StudyIndex& index, bool include_unfinished) {
    return InputError(include_unfinished ? "the study has no run with statistics yet"
                                         : "the study has no done run to plot (--include-unfinished also plots "
                                           "the others)",
                      index.file.string());
}

std::string study_name(const fs::path& study) {
    fs::path p = study;
    if (!p.has_filename()) p = p.parent_path();
    return fs::weakly_canonical(p).filename().string();
}

} // namespace

SearchKind search_kind_of(const fs::path& run_dir) {
    try {
        const io::Settings s = io::read_settings(run_dir / "settings.xml");
        if (s.map_elites.enabled) return SearchKind::MapElites;
        if (io::family_of(s) == io::ExperimentFamily::Gait) return SearchKind::Gait;
    } catch (const std::exception&) {
        // no readable settings: today's panels
    }
    return SearchKind::GP;
}

std::string x_axis_name(SearchKind kind) { return kind == SearchKind::MapElites ? "batch" : "generation"; }

std::vector<int> restart_generations(const fs::path& run_dir) {
    try {
        const fs::path file = run_dir / "population.xml";
        if (!io::is_gait_file(file)) return {};
        const io::GaitFile g = io::load_gait(file);
        return g.restarts ? g.restarts->generations : std::vector<int>{};
    } catch (const std::exception&) {
        return {};
    }
}

namespace {

// The search every run shares; InputError naming the first run of another.
SearchKind common_search(const std::vector<fs::path>& runs) {
    const SearchKind kind = search_kind_of(runs.front());
    for (const fs::path& run : runs)
        if (search_kind_of(run) != kind)
            throw InputError(fmt::format("runs of different searches (GP, gait, MAP-Elites) do not share panels: {} "
                                         "and {} differ (plot them apart, or compare studies with --by-evaluations)",
                                         runs.front().string(), run.string()),
                             run.string());
    return kind;
}

// A panel: its title, y label, the plot command and lines to run before it
// (e.g. restart markers) and after it.
struct Panel {
    std::string title, ylabel, plot, before, after;
};

std::string panels_script(const std::vector<Panel>& panels) {
    std::string script;
    for (const Panel& p : panels)
        script += fmt::format("set title {}\nset ylabel {}\n{}{}{}", quote(p.title), quote(p.ylabel), p.before,
                              p.plot, p.after);
    return script;
}

// The figure's frame: terminal, output, layout for `panels` panels, axes.
std::string figure_start(const fs::path& out_file, const PlotOptions& options, const fs::path& scratch,
                         std::size_t panels, const std::string& title, const std::string& xlabel,
                         const std::string& data_file) {
    const int columns = panels == 1 ? 1 : 2;
    const int rows = static_cast<int>((panels + 1) / 2);
    const int width = options.width > 0 ? options.width : 600 * columns;
    const int height = options.height > 0 ? options.height : 100 + 400 * rows;
    std::string script = terminal_for(out_file, width, height, options.gnuplot, scratch) + "\n";
    script += fmt::format("set output {}\n", quote(out_file.string()));
    script += fmt::format("set multiplot layout {},{}{}\n", rows, columns, title.empty() ? "" : " title " + quote(title));
    // The key's box a line taller than gnuplot makes it: a tight one draws its
    // bottom edge over the underscores of the last label in PNG output.
    script += "set grid\nset key left top box opaque height 1\nset autoscale xfix\n";
    // Room above and below the curves: a constant line would lie on the frame.
    script += "set offsets 0, 0, graph 0.05, graph 0.05\n";
    script += fmt::format("set xlabel {}\n", quote(xlabel));
    script += generation_ticks(data_file);
    return script;
}

// Vertical dashed lines at each restart, in the run's colour.
std::string restart_markers(const std::vector<int>& generations, const std::string& colour) {
    std::string s;
    for (int g : generations)
        s += fmt::format("set arrow from {},graph 0 to {},graph 1 nohead dt 3 lw 1.5 lc {}\n", g, g, colour);
    return s;
}

} // namespace

void plot_runs(const std::vector<fs::path>& run_dirs, const fs::path& out_file, const PlotOptions& options) {
    if (run_dirs.empty()) throw InputError("plot: give at least one run folder");
    check_output_folder(out_file);
    const SearchKind kind = common_search(run_dirs);
    const auto groups = group_runs(run_dirs);
    ScratchDir scratch;

    std::vector<std::string> data_files;
    bool best_falls = false;   // a generation's best below the best so far (GP without elitism)
    for (std::size_t g = 0; g < groups.size(); ++g) {
        std::vector<std::vector<StatsRow>> runs;
        for (const auto& dir : groups[g].runs) runs.push_back(read_stats_csv(dir / "stats.csv"));
        for (const auto& run : runs)
            for (const StatsRow& r : run) best_falls = best_falls || r.best < r.best_so_far;
        std::string text = "# generation runs best best_sd mean mean_sd mean_depth max_depth mean_size max_size "
                           "best_so_far best_so_far_sd qd_score qd_score_sd coverage coverage_sd\n";
        for (const auto& s : summarise(runs))
            text += fmt::format("{} {} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g} "
                                "{:.10g} {:.10g} {:.10g} {:.10g}\n",
                                s.generation, s.runs, s.best, s.best_sd, s.mean, s.mean_sd, s.mean_depth, s.max_depth,
                                s.mean_size, s.max_size, s.best_so_far, s.best_so_far_sd, s.qd_score, s.qd_score_sd,
                                s.coverage, s.coverage_sd);
        const fs::path data = scratch.path() / fmt::format("group{}.dat", g);
        write_file(data, text);
        data_files.push_back(quote(data.string()));
    }

    auto label = [&](std::size_t g) {
        const auto n = groups[g].runs.size();
        return n > 1 ? fmt::format("{} ({} runs)", groups[g].label, n) : groups[g].label;
    };
    auto colour = [](std::size_t g) { return fmt::format("rgb '{}'", kColours[g % kColours.size()]); };
    // Mean curve of column `col` with a +-1 sd band (column sd_col) for groups of
    // several runs; with dashed_col, a thin dashed companion curve (no band).
    auto curves = [&](int col, int sd_col, const std::string& suffix = "", int dashed_col = 0,
                      const std::string& dashed_suffix = "") {
        std::vector<std::string> items;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            if (groups[g].runs.size() > 1)
                items.push_back(fmt::format("{} using 1:(${}-${}):(${}+${}) with filledcurves fs transparent solid 0.18 "
                                            "noborder lc {} notitle",
                                            data_files[g], col, sd_col, col, sd_col, colour(g)));
            items.push_back(fmt::format("{} using 1:{} with lines lw 2 lc {} title {}", data_files[g], col, colour(g),
                                        quote(label(g) + suffix)));
            if (dashed_col > 0)
                items.push_back(fmt::format("{} using 1:{} with lines lw 1 dt 2 lc {} title {}", data_files[g],
                                            dashed_col, colour(g), quote(label(g) + dashed_suffix)));
        }
        return fmt::format("plot {}\n", fmt::join(items, ", \\\n  "));
    };
    auto mean_max = [&](const char* what, int mean_col, int max_col) {
        std::vector<std::string> items;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            items.push_back(fmt::format("{} using 1:{} with lines lw 2 lc {} title {}", data_files[g], max_col,
                                        colour(g), quote(label(g) + " max " + what)));
            items.push_back(fmt::format("{} using 1:{} with lines lw 2 dt 2 lc {} title {}", data_files[g], mean_col,
                                        colour(g), quote(label(g) + " mean " + what)));
        }
        return fmt::format("plot {}\n", fmt::join(items, ", \\\n  "));
    };

    const std::string fitness = fitness_label(run_dirs.front());
    std::vector<Panel> panels;
    switch (kind) {
    case SearchKind::GP:
        panels = {best_falls ? Panel{"best fitness (solid: each generation's, dashed: so far)", fitness,
                                     curves(3, 4, "", 11, " so far"), "", ""}
                             : Panel{"best fitness", fitness, curves(3, 4), "", ""},
                  {"mean fitness", fitness, curves(5, 6), "", ""},
                  {"depth (solid: max, dashed: mean)", "depth", mean_max("depth", 7, 8), "", ""},
                  {"size (solid: max, dashed: mean)", "size", mean_max("size", 9, 10), "", ""}};
        break;
    case SearchKind::Gait: {
        std::string markers;
        for (std::size_t g = 0; g < groups.size(); ++g)
            for (const auto& dir : groups[g].runs) markers += restart_markers(restart_generations(dir), colour(g));
        panels = {{markers.empty() ? "best fitness (solid: so far, dashed: each generation's)"
                                   : "best fitness (solid: so far, dashed: each generation's; dotted: IPOP restarts)",
                   fitness, curves(11, 12, " so far", 3, " generation's best"), markers, "unset arrow\n"},
                  {"mean fitness of each generation's candidates", fitness, curves(5, 6), "", ""}};
        break;
    }
    case SearchKind::MapElites:
        panels = {{"QD-score (sum of elites' fitness - MapElites.qdOffset)", "QD-score", curves(13, 14), "", ""},
                  {"coverage (share of cells filled)", "coverage", curves(15, 16), "", ""},
                  {"best elite (the best so far)", fitness, curves(11, 12), "", ""},
                  {"mean fitness of the archive's elites", fitness, curves(5, 6), "", ""}};
        break;
    }
    std::string script = figure_start(out_file, options, scratch.path(), panels.size(), options.title,
                                      x_axis_name(kind), data_files.front());
    script += panels_script(panels);
    script += "unset multiplot\nset output\n";
    render(options.gnuplot, scratch.path(), script, out_file);
}

void plot_study(const fs::path& study, const fs::path& out_file, const StudyPlotOptions& options) {
    check_output_folder(out_file);
    const StudyIndex index = read_study_index(study);
    std::vector<BandSeries> series;
    std::vector<fs::path> shown_runs;
    ScratchDir scratch;
    for (const auto& group : group_study(index, options.include_unfinished)) {
        const auto runs = stats_of(index, group);
        if (runs.empty()) continue;
        for (const StudyRun* r : group.runs) shown_runs.push_back(index.run_path(*r));
        std::string text = "# generation runs then centre low high of: best mean mean_depth max_depth best_so_far "
                           "qd_score coverage\n";
        for (const auto& g : summarise_bands(runs, options.median)) {
            text += fmt::format("{} {}", g.generation, g.runs);
            for (const Band& b : {g.best, g.mean, g.mean_depth, g.max_depth, g.best_so_far, g.qd_score, g.coverage})
                text += fmt::format(" {:.10g} {:.10g} {:.10g}", b.centre, b.low, b.high);
            text += '\n';
        }
        const fs::path data = scratch.path() / fmt::format("config{}.dat", series.size());
        write_file(data, text);
        series.push_back({group.config, runs.size(), quote(data.string())});
    }
    if (series.empty())
        throw nothing_to_plot(index, options.include_unfinished);
    const SearchKind kind = common_search(shown_runs);

    const std::string band_name = options.median ? "median, IQR band" : "mean, +-1 sd band";
    auto panel = [&](const std::string& title, const std::string& ylabel, int col) {
        return Panel{title + " (" + band_name + ")", ylabel, band_plot_command(series, col), "", ""};
    };
    const std::string fitness = fitness_label(index.run_path(index.runs.front()));
    std::vector<Panel> panels;
    switch (kind) {
    case SearchKind::GP:
        panels = {panel("best fitness", fitness, 3), panel("mean fitness", fitness, 6),
                  panel("max depth", "depth", 12), panel("mean depth", "depth", 9)};
        break;
    case SearchKind::Gait: {
        // Every run's IPOP restarts, dotted in its configuration's colour.
        std::string markers;
        std::size_t k = 0;
        for (const auto& group : group_study(index, options.include_unfinished)) {
            if (stats_of(index, group).empty()) continue;
            const std::string colour = fmt::format("rgb '{}'", kColours[k++ % kColours.size()]);
            for (const StudyRun* r : group.runs) markers += restart_markers(restart_generations(index.run_path(*r)), colour);
        }
        panels = {panel(markers.empty() ? "best fitness so far" : "best fitness so far (dotted: IPOP restarts)", fitness,
                        15),
                  panel("each generation's best", fitness, 3),
                  panel("mean fitness of each generation's candidates", fitness, 6)};
        panels.front().before = markers;
        panels.front().after = "unset arrow\n";
        break;
    }
    case SearchKind::MapElites:
        panels = {panel("QD-score", "QD-score", 18), panel("coverage", "coverage", 21),
                  panel("best elite (the best so far)", fitness, 15), panel("mean fitness of the elites", fitness, 6)};
        break;
    }
    const std::string title = options.title.empty() ? "study " + study_name(study) : options.title;
    std::string script = figure_start(out_file, options, scratch.path(), panels.size(), title, x_axis_name(kind),
                                      series.front().data);
    script += panels_script(panels);
    script += "unset multiplot\nset output\n";
    render(options.gnuplot, scratch.path(), script, out_file);
}

void plot_studies_by_evaluations(const std::vector<fs::path>& studies, const fs::path& out_file,
                                 const EvaluationPlotOptions& options) {
    if (studies.empty()) throw InputError("plot: give at least one study folder");
    check_output_folder(out_file);
    const bool one_per_study = options.configs.size() == 1;
    std::string by_evaluations_label;   // the first study's, with its unit
    std::vector<BandSeries> series;
    ScratchDir scratch;
    for (const auto& study : studies) {
        const StudyIndex index = read_study_index(study);
        if (by_evaluations_label.empty() && !index.runs.empty())
            by_evaluations_label = fitness_label(index.run_path(index.runs.front()), "best fitness so far");
        const auto groups = group_study(index, options.include_unfinished);
        std::vector<const StudyGroup*> chosen;
        if (options.configs.empty()) {
            for (const auto& g : groups) chosen.push_back(&g);
        } else {
            for (const auto& name : options.configs) {
                const auto it = std::find_if(groups.begin(), groups.end(),
                                             [&](const StudyGroup& g) { return g.config == name; });
                if (it == groups.end()) {
                    std::vector<std::string> names;
                    for (const auto& g : groups) names.push_back(g.config);
                    throw InputError(fmt::format("no configuration '{}' in the study (it has: {})", name,
                                                 fmt::join(names, ", ")),
                                     index.file.string());
                }
                chosen.push_back(&*it);
            }
        }
        const std::size_t before = series.size();
        for (const StudyGroup* group : chosen) {
            const auto runs = stats_of(index, *group);
            if (runs.empty()) continue;
            std::string text = "# evaluations runs best_so_far low high\n";
            for (const auto& b : summarise_by_evaluations(runs, options.median))
                text += fmt::format("{:.10g} {} {:.10g} {:.10g} {:.10g}\n", b.evaluations, b.runs,
                                    b.best_so_far.centre, b.best_so_far.low, b.best_so_far.high);
            const fs::path data = scratch.path() / fmt::format("series{}.dat", series.size());
            write_file(data, text);
            const std::string name = study_name(study);
            series.push_back({one_per_study ? name : name + ": " + group->config, runs.size(), quote(data.string())});
        }
        if (series.size() == before)
            throw nothing_to_plot(index, options.include_unfinished);
    }

    const int width = options.width > 0 ? options.width : 900;
    const int height = options.height > 0 ? options.height : 600;
    const std::string band_name = options.median ? "median, IQR band" : "mean, +-1 sd band";
    const std::string title = options.title.empty() ? "best fitness so far" : options.title;
    std::string script = terminal_for(out_file, width, height, options.gnuplot, scratch.path()) + "\n";
    script += fmt::format("set output {}\n", quote(out_file.string()));
    script += fmt::format("set title {}\n", quote(title + " (" + band_name + ")"));
    script += "set grid\nset key left top box opaque height 1\nset xlabel 'evaluations'\nset autoscale xfix\n";
    script += fmt::format("set ylabel {}\n", quote(by_evaluations_label.empty() ? "best fitness so far" : by_evaluations_label));
    script += band_plot_command(series, 3);
    script += "set output\n";
    render(options.gnuplot, scratch.path(), script, out_file);
}

void plot_trace(const fs::path& trace_csv, const fs::path& out_file, const TracePlotOptions& options) {
    check_output_folder(out_file);
    if (!(options.from < options.to)) throw InputError("plot: --from must be before --to");
    const TraceTable table = read_trace_csv(trace_csv);
    std::vector<std::size_t> chosen;
    if (options.joints.empty()) {
        for (std::size_t j = 0; j < table.joints.size(); ++j) chosen.push_back(j);
    } else {
        for (const auto& name : options.joints) {
            const auto it = std::find(table.joints.begin(), table.joints.end(), name);
            if (it == table.joints.end())
                throw InputError(fmt::format("no joint '{}' in the trace (joints: {})", name,
                                             fmt::join(table.joints, ", ")),
                                 trace_csv.string());
            chosen.push_back(static_cast<std::size_t>(it - table.joints.begin()));
        }
    }
    if (chosen.empty()) throw InputError("the trace has no joints", trace_csv.string());

    ScratchDir scratch;
    std::string text = "# t then per chosen joint: output command angle\n";
    std::size_t kept = 0;
    for (const auto& row : table.rows) {
        if (row.t < options.from || row.t > options.to) continue;
        ++kept;
        text += fmt::format("{:.10g}", row.t);
        for (std::size_t j : chosen)
            text += fmt::format(" {:.10g} {:.10g} {:.10g}", row.outputs[j], row.commands[j], row.angles[j]);
        text += '\n';
    }
    if (kept == 0) throw InputError("no trace rows in the chosen time window", trace_csv.string());
    const fs::path data = scratch.path() / "trace.dat";
    write_file(data, text);

    const int columns = chosen.size() > 6 ? 2 : 1;
    const int rows = static_cast<int>((chosen.size() + static_cast<std::size_t>(columns) - 1) /
                                      static_cast<std::size_t>(columns));
    const int width = options.width > 0 ? options.width : 900 * columns;
    const int height = options.height > 0 ? options.height : 80 + 210 * rows;
    std::string script = terminal_for(out_file, width, height, options.gnuplot, scratch.path()) + "\n";
    script += fmt::format("set output {}\n", quote(out_file.string()));
    // The one legend of the figure is its title's second line: every panel draws the same three lines.
    const std::string legend = "grey: raw output (right axis), blue: command, red dashed: angle";
    std::string heading;   // in a gnuplot double-quoted string, where \n breaks the line
    for (char c : options.title.empty() ? trace_csv.filename().string() : options.title) {
        if (c == '\\' || c == '"') heading += '\\';
        heading += c;
    }
    script += fmt::format("set multiplot layout {},{} columnsfirst title \"{}\\n{}\"\n", rows, columns, heading, legend);
    // Commands and angles are angles (left axis, rad); the raw output is the
    // controller's own unitless value in [-1, 1] (right axis).
    script += "set grid\nunset key\nset xlabel 't [s]'\nset ylabel 'angle [rad]'\n"
              "set y2label 'raw output'\nset y2range [-1.05:1.05]\nset y2tics -1,0.5,1\nset ytics nomirror\n"
              "set autoscale xfix\n";
    for (std::size_t k = 0; k < chosen.size(); ++k) {
        const std::size_t base = 2 + 3 * k;
        script += fmt::format("set title {}\n", quote("joint " + table.joints[chosen[k]]));
        script += fmt::format(
            "plot {0} using 1:{1} axes x1y2 with lines lw 1 lc rgb '#999999' title 'raw output', \\\n"
            "  {0} using 1:{2} with lines lw 2 lc rgb '#1f77b4' title 'command', \\\n"
            "  {0} using 1:{3} with lines lw 2 dt 2 lc rgb '#d62728' title 'angle'\n",
            quote(data.string()), base, base + 1, base + 2);
    }
    script += "unset multiplot\nset output\n";
    render(options.gnuplot, scratch.path(), script, out_file);
}

} // namespace cic::report
