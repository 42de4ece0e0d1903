// gnuplot scripts for run statistics and network traces.
#include "cic/report/plot.hpp"

#include "cic/io/experiment_types.hpp"
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

namespace cic::app {
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

void plot_runs(const std::vector<fs::path>& run_dirs, const fs::path& out_file, const PlotOptions& options) {
    if (run_dirs.empty()) throw InputError("plot: give at least one run folder");
    check_output_folder(out_file);
    const auto groups = group_runs(run_dirs);
    ScratchDir scratch;

    std::vector<std::string> data_files;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        std::vector<std::vector<StatsRow>> runs;
        for (const auto& dir : groups[g].runs) runs.push_back(read_stats_csv(dir / "stats.csv"));
        std::string text = "# generation runs best best_sd mean mean_sd mean_depth max_depth mean_size max_size\n";
        for (const auto& s : summarise(runs))
            text += fmt::format("{} {} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g}\n", s.generation,
                                s.runs, s.best, s.best_sd, s.mean, s.mean_sd, s.mean_depth, s.max_depth, s.mean_size,
                                s.max_size);
        const fs::path data = scratch.path() / fmt::format("group{}.dat", g);
        write_file(data, text);
        data_files.push_back(quote(data.string()));
    }

    auto label = [&](std::size_t g) {
        const auto n = groups[g].runs.size();
        return n > 1 ? fmt::format("{} ({} runs)", groups[g].label, n) : groups[g].label;
    };
    auto colour = [](std::size_t g) { return fmt::format("rgb '{}'", kColours[g % kColours.size()]); };
    // Mean curve of column `col` with a +-1 sd band (column sd_col) for groups of several runs.
    auto fitness_panel = [&](const char* title, int col, int sd_col) {
        std::vector<std::string> items;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            if (groups[g].runs.size() > 1)
                items.push_back(fmt::format("{} using 1:(${}-${}):(${}+${}) with filledcurves fs transparent solid 0.18 "
                                            "noborder lc {} notitle",
                                            data_files[g], col, sd_col, col, sd_col, colour(g)));
            items.push_back(fmt::format("{} using 1:{} with lines lw 2 lc {} title {}", data_files[g], col, colour(g),
                                        quote(label(g))));
        }
        return fmt::format("set title {}\nset ylabel {}\nplot {}\n", quote(title), quote(fitness_label(run_dirs.front())),
                           fmt::join(items, ", \\\n  "));
    };
    auto mean_max_panel = [&](const char* title, const char* what, int mean_col, int max_col) {
        std::vector<std::string> items;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            items.push_back(fmt::format("{} using 1:{} with lines lw 2 lc {} title {}", data_files[g], max_col,
                                        colour(g), quote(label(g) + " max " + what)));
            items.push_back(fmt::format("{} using 1:{} with lines lw 2 dt 2 lc {} title {}", data_files[g], mean_col,
                                        colour(g), quote(label(g) + " mean " + what)));
        }
        return fmt::format("set title {}\nset ylabel {}\nplot {}\n", quote(title), quote(what),
                           fmt::join(items, ", \\\n  "));
    };

    const int width = options.width > 0 ? options.width : 1200;
    const int height = options.height > 0 ? options.height : 900;
    std::string script = terminal_for(out_file, width, height, options.gnuplot, scratch.path()) + "\n";
    script += fmt::format("set output {}\n", quote(out_file.string()));
    script += fmt::format("set multiplot layout 2,2{}\n",
                          options.title.empty() ? "" : " title " + quote(options.title));
    script += "set grid\nset key left top box opaque\nset xlabel 'generation'\nset autoscale xfix\n";
    script += generation_ticks(data_files.front());
    script += fitness_panel("best fitness", 3, 4);
    script += fitness_panel("mean fitness", 5, 6);
    script += mean_max_panel("depth (solid: max, dashed: mean)", "depth", 7, 8);
    script += mean_max_panel("size (solid: max, dashed: mean)", "size", 9, 10);
    script += "unset multiplot\nset output\n";
    render(options.gnuplot, scratch.path(), script, out_file);
}

void plot_study(const fs::path& study, const fs::path& out_file, const StudyPlotOptions& options) {
    check_output_folder(out_file);
    const StudyIndex index = read_study_index(study);
    std::vector<BandSeries> series;
    ScratchDir scratch;
    for (const auto& group : group_study(index, options.include_unfinished)) {
        const auto runs = stats_of(index, group);
        if (runs.empty()) continue;
        std::string text = "# generation runs then centre low high of: best mean mean_depth max_depth\n";
        for (const auto& g : summarise_bands(runs, options.median)) {
            text += fmt::format("{} {}", g.generation, g.runs);
            for (const Band& b : {g.best, g.mean, g.mean_depth, g.max_depth})
                text += fmt::format(" {:.10g} {:.10g} {:.10g}", b.centre, b.low, b.high);
            text += '\n';
        }
        const fs::path data = scratch.path() / fmt::format("config{}.dat", series.size());
        write_file(data, text);
        series.push_back({group.config, runs.size(), quote(data.string())});
    }
    if (series.empty())
        throw nothing_to_plot(index, options.include_unfinished);

    const std::string band_name = options.median ? "median, IQR band" : "mean, +-1 sd band";
    auto panel = [&](const std::string& title, const char* ylabel, int col) {
        return fmt::format("set title {}\nset ylabel {}\n{}", quote(title + " (" + band_name + ")"), quote(ylabel),
                           band_plot_command(series, col));
    };

    const int width = options.width > 0 ? options.width : 1200;
    const int height = options.height > 0 ? options.height : 900;
    const std::string title = options.title.empty() ? "study " + study_name(study) : options.title;
    std::string script = terminal_for(out_file, width, height, options.gnuplot, scratch.path()) + "\n";
    script += fmt::format("set output {}\n", quote(out_file.string()));
    script += fmt::format("set multiplot layout 2,2 title {}\n", quote(title));
    script += "set grid\nset key left top box opaque\nset xlabel 'generation'\nset autoscale xfix\n";
    const std::string fitness = fitness_label(index.run_path(index.runs.front()));
    script += generation_ticks(series.front().data);
    script += panel("best fitness", fitness.c_str(), 3);
    script += panel("mean fitness", fitness.c_str(), 6);
    script += panel("max depth", "depth", 12);
    script += panel("mean depth", "depth", 9);
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
    script += "set grid\nset key left top box opaque\nset xlabel 'evaluations'\nset autoscale xfix\n";
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

} // namespace cic::app
