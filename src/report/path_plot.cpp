// The centre's path seen from above (path_plot.hpp).
#include "cic/report/path_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cic/core/error.hpp"
#include "gnuplot_support.hpp"

namespace cic::report {

namespace fs = std::filesystem;

namespace {

constexpr std::array<const char*, 8> kColours = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                                 "#9467bd", "#8c564b", "#e377c2", "#17becf"};

std::string folder_name(const fs::path& dir) {
    fs::path p = dir;
    if (!p.has_filename()) p = p.parent_path();
    return fs::weakly_canonical(p).filename().string();
}

CentrePath replayed_path(const fs::path& run, std::string label) {
    auto items = replay(run.string(), "best", 1, 10.0, true);
    return centre_path(items.front(), std::move(label));
}

} // namespace

const StudyRun* best_run_of(const StudyGroup& group) {
    const StudyRun* best = nullptr;
    auto score = [](const StudyRun& r) { return r.best_ever ? *r.best_ever : r.final_best.value_or(-INFINITY); };
    for (const StudyRun* r : group.runs)
        if (!best || score(*r) > score(*best)) best = r;
    return best;
}

CentrePath centre_path(const ReplayItem& item, std::string label) {
    CentrePath p;
    p.label = std::move(label);
    if (!item.trace.empty()) {
        for (const auto& row : item.trace) p.xy.push_back({row.centre[0], row.centre[1]});
    } else {
        const auto body = static_cast<std::size_t>(item.centre_body);
        for (const auto& frame : item.recording.frames)
            if (body < frame.size()) p.xy.push_back({frame[body].pos[0], frame[body].pos[1]});
    }
    if (p.xy.empty()) throw std::invalid_argument("centre_path: the replay has no trace and no recorded frames");
    p.measured_from = {item.measured_from[0], item.measured_from[1]};
    p.measured_to = {item.measured_to[0], item.measured_to[1]};
    p.preferred_axis = item.preferred_axis;
    p.distance = item.distance;
    p.fitness = item.replayed_fitness;
    return p;
}

std::vector<CentrePath> best_paths(const std::vector<fs::path>& runs_or_study, bool include_unfinished) {
    std::vector<CentrePath> paths;
    if (runs_or_study.size() == 1 && is_study_folder(runs_or_study.front())) {
        const StudyIndex index = read_study_index(runs_or_study.front());
        for (const StudyGroup& group : group_study(index, include_unfinished)) {
            const StudyRun* run = best_run_of(group);
            if (!run) continue;
            paths.push_back(replayed_path(index.run_path(*run), fmt::format("{} (seed {})", group.config, run->seed)));
        }
        if (paths.empty())
            throw InputError("the study has no done run to show (--include-unfinished also shows the others)",
                             index.file.string());
        return paths;
    }
    for (const fs::path& run : runs_or_study) paths.push_back(replayed_path(run, folder_name(run)));
    return paths;
}

void plot_paths(const std::vector<CentrePath>& paths, const fs::path& out_file, const PlotOptions& options) {
    if (paths.empty()) throw std::invalid_argument("plot_paths: no paths");
    detail::check_output_folder(out_file);
    detail::ScratchDir scratch;
    double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
    std::vector<std::string> items;
    std::string inline_data;   // eq. 7.1's start of each path, after the plot command
    for (std::size_t k = 0; k < paths.size(); ++k) {
        const CentrePath& p = paths[k];
        std::string text;
        for (const auto& [x, y] : p.xy) {
            text += fmt::format("{:.10g} {:.10g}\n", x, y);
            lo_x = std::min(lo_x, x), hi_x = std::max(hi_x, x), lo_y = std::min(lo_y, y), hi_y = std::max(hi_y, y);
        }
        const fs::path data = scratch.path() / fmt::format("path{}.dat", k);
        detail::write_file(data, text);
        const std::string file = detail::quote(data.string());
        const std::string colour = fmt::format("rgb '{}'", kColours[k % kColours.size()]);
        const std::string label =
            fmt::format("{}: {:.3f} m along {} (fitness {:.3f})", p.label, p.distance, p.preferred_axis == 0 ? "x" : "y",
                        p.fitness);
        items.push_back(fmt::format("{} using 1:2 with lines lw 2 lc {} title {}", file, colour, detail::quote(label)));
        items.push_back(fmt::format("{} every ::0::0 using 1:2 with points pt 7 ps 1.6 lc {} notitle", file, colour));
        items.push_back(fmt::format("{} every ::{}::{} using 1:2 with points pt 2 ps 2 lw 2 lc {} notitle", file,
                                    p.xy.size() - 1, p.xy.size() - 1, colour));
        items.push_back(fmt::format("'-' using 1:2 with points pt 4 ps 1.4 lw 2 lc {} notitle", colour));
        inline_data += fmt::format("{:.10g} {:.10g}\ne\n", p.measured_from[0], p.measured_from[1]);
    }
    // The preferred axis: an arrow from the first path's eq. 7.1 start, as long as the widest path.
    const CentrePath& first = paths.front();
    const double span = std::max({hi_x - lo_x, hi_y - lo_y, 0.2});
    const double ax = first.measured_from[0], ay = first.measured_from[1];
    const double bx = first.preferred_axis == 0 ? ax + 0.5 * span : ax;
    const double by = first.preferred_axis == 0 ? ay : ay + 0.5 * span;
    const double margin = 0.12 * span;
    // Equal scales, and at least a third as tall as wide so that the legend and label fit.
    double x0 = std::min(lo_x, ax) - margin, x1 = std::max(hi_x, bx) + margin;
    double y0 = std::min(lo_y, ay) - margin, y1 = std::max(hi_y, by) + margin;
    if (y1 - y0 < (x1 - x0) / 3) {
        const double grow = ((x1 - x0) / 3 - (y1 - y0)) / 2;
        y0 -= grow, y1 += grow;
    }
    const double aspect = (y1 - y0) / (x1 - x0);
    const int width = options.width > 0 ? options.width : 800;
    const int height = options.height > 0 ? options.height
                                          : static_cast<int>(std::clamp(200 + 40 * paths.size() + 620 * aspect, 380.0, 1000.0));
    std::string script = detail::terminal_for(out_file, width, height, options.gnuplot, scratch.path()) + "\n";
    script += fmt::format("set output {}\n", detail::quote(out_file.string()));
    script += fmt::format("set title {}\n",
                          detail::quote(options.title.empty()
                                            ? "the centre's path from above (circle: start, square: eq. 7.1's start "
                                              "after the delay, cross: end)"
                                            : options.title));
    script += "set xlabel 'x [m]'\nset ylabel 'y [m]'\nset grid\nset size ratio -1\n"
              "set key outside bottom center vertical box opaque height 1\n";
    script += fmt::format("set xrange [{:.10g}:{:.10g}]\nset yrange [{:.10g}:{:.10g}]\n", x0, x1, y0, y1);
    script += fmt::format("set arrow 1 from {:.10g},{:.10g} to {:.10g},{:.10g} head filled size screen 0.015,20 lw 2 "
                          "dt 2 lc rgb '#444444' back\n",
                          ax, ay, bx, by);
    script += fmt::format("set label 1 {} at {:.10g},{:.10g} {} textcolor rgb '#444444' back\n",
                          detail::quote(fmt::format("preferred axis {} (eq. 7.1)", first.preferred_axis == 0 ? "x" : "y")),
                          ax, ay, first.preferred_axis == 0 ? "left offset 1,-1.2" : "left offset 1,0");
    script += fmt::format("plot {}\n", fmt::join(items, ", \\\n  "));
    script += inline_data;
    script += "set output\n";
    detail::render(options.gnuplot, scratch.path(), script, out_file);
}

} // namespace cic::report
