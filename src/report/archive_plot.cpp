// MAP-Elites archives as heatmaps (archive_plot.hpp).
#include "cic/report/archive_plot.hpp"

#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/sim/evaluate.hpp"
#include "gnuplot_support.hpp"

namespace cic::report {

namespace fs = std::filesystem;

ArchiveMap collapse_archive(const io::ArchiveFile& a, std::size_t x_dim, std::size_t y_dim) {
    const std::size_t dims = a.grid.dimensions();
    if (x_dim >= dims || y_dim >= dims)
        throw InputError(fmt::format("the archive has {} descriptor dimension{} (1 to {}); asked for {} and {}", dims,
                                     dims == 1 ? "" : "s", dims, x_dim + 1, y_dim + 1));
    if (x_dim == y_dim && dims > 1) throw InputError("show two different descriptor dimensions");
    ArchiveMap m;
    m.x_dim = x_dim;
    m.y_dim = y_dim;
    m.x_bins = a.grid.bins[x_dim];
    m.x_lo = a.grid.lo[x_dim];
    m.x_hi = a.grid.hi[x_dim];
    if (dims > 1) {
        m.y_bins = a.grid.bins[y_dim];
        m.y_lo = a.grid.lo[y_dim];
        m.y_hi = a.grid.hi[y_dim];
    }
    m.best.assign(static_cast<std::size_t>(m.x_bins) * static_cast<std::size_t>(m.y_bins),
                  std::numeric_limits<double>::quiet_NaN());
    for (const io::ArchiveElite& e : a.elites) {
        const std::vector<int> bins = a.grid.coordinates(e.cell);
        const int y = dims > 1 ? bins[y_dim] : 0;
        double& v = m.best[static_cast<std::size_t>(y) * static_cast<std::size_t>(m.x_bins) +
                           static_cast<std::size_t>(bins[x_dim])];
        if (std::isnan(v) || e.fitness > v) v = e.fitness;
    }
    return m;
}

ArchiveSlices slice_layout(const gp::GridSpec& grid, std::size_t x_dim, std::size_t y_dim) {
    const std::size_t dims = grid.dimensions();
    if (x_dim >= dims || (dims > 1 && y_dim >= dims))
        throw InputError(fmt::format("the archive has {} descriptor dimension{} (1 to {}); asked for {} and {}", dims,
                                     dims == 1 ? "" : "s", dims, x_dim + 1, y_dim + 1));
    if (x_dim == y_dim && dims > 1) throw InputError("show two different descriptor dimensions");
    ArchiveSlices l;
    l.x_dim = x_dim;
    l.y_dim = dims > 1 ? y_dim : x_dim;
    l.x_bins = grid.bins[x_dim];
    l.y_bins = dims > 1 ? grid.bins[y_dim] : 1;
    for (std::size_t d = 0; d < dims && l.outer.size() < 2; ++d)
        if (d != l.x_dim && d != l.y_dim) l.outer.push_back(d);
    if (!l.outer.empty()) l.blocks_x = grid.bins[l.outer[0]];
    if (l.outer.size() > 1) l.blocks_y = grid.bins[l.outer[1]];
    return l;
}

std::array<double, 2> ArchiveSlices::centre_of(const std::vector<int>& bins) const {
    const int bx = outer.empty() ? 0 : bins[outer[0]];
    const int by = outer.size() > 1 ? bins[outer[1]] : 0;
    const int y = y_dim == x_dim ? 0 : bins[y_dim];
    return {bx * (x_bins + 1) + bins[x_dim] + 0.5, by * (y_bins + 1) + y + 0.5};
}

bool is_archive_run(const fs::path& run_dir) {
    try {
        return fs::is_regular_file(run_dir / "settings.xml") &&
               io::read_settings(run_dir / "settings.xml").map_elites.enabled;
    } catch (const std::exception&) {
        return false;
    }
}

namespace {

std::string dimension_name(const io::Settings& s, const sim::RobotSpec& robot, std::size_t dim) {
    if (s.map_elites.descriptor == sim::Descriptor::Omni) return dim == 0 ? "x displacement [m]" : "y displacement [m]";
    const std::vector<int> feet = sim::branch_ends(robot);
    const int m = feet.at(dim);
    const std::string& name = robot.modules[static_cast<std::size_t>(m)].name;
    return fmt::format("duty factor, foot {}", name.empty() ? "m" + std::to_string(m) : name);
}

// "dimension D (NAME): bins of W from LO": what a bin number means.
std::string bins_label(const io::Settings& s, const sim::RobotSpec& robot, const gp::GridSpec& grid, std::size_t dim) {
    const double w = (grid.hi[dim] - grid.lo[dim]) / grid.bins[dim];
    return fmt::format("dimension {} ({}): bin i covers [{:.4g} + {:.4g} i, {:.4g} + {:.4g} (i+1))", dim + 1,
                       dimension_name(s, robot, dim), grid.lo[dim], w, grid.lo[dim], w);
}

// Tics at each bin's centre, numbered, repeated in every block; every k-th bin
// when there are many.
std::string bin_tics(const char* axis, int bins, int blocks) {
    const int every = std::max(1, bins / 10);
    std::vector<std::string> tics;
    for (int b = 0; b < blocks; ++b)
        for (int i = 0; i < bins; i += every) tics.push_back(fmt::format("\"{}\" {:g}", i, b * (bins + 1) + i + 0.5));
    return fmt::format("set {}tics ({}) scale 0\n", axis, fmt::join(tics, ", "));
}

} // namespace

void plot_archive(const fs::path& input, const fs::path& out_file, const ArchivePlotOptions& options) {
    detail::check_output_folder(out_file);
    const fs::path run = fs::is_directory(input) ? input : input.parent_path().parent_path();
    const fs::path archive_file = fs::is_directory(input) ? input / "population.xml" : input;
    if (!fs::is_regular_file(run / "settings.xml"))
        throw InputError("not a run folder (no settings.xml)", run.string());
    const io::Settings s = io::read_settings(run / "settings.xml");
    if (!s.map_elites.enabled)
        throw InputError("--archive plots a MAP-Elites run's archive; this run has none (MapElites.enabled is 0)",
                         (run / "settings.xml").string());
    if (!fs::is_regular_file(archive_file))
        throw InputError("the run has no archive yet (no batch has finished)", archive_file.string());
    const io::ArchiveFile a = io::load_archive(archive_file);
    const std::size_t dims = a.grid.dimensions();
    const ArchiveSlices l = slice_layout(a.grid, options.x_dim, dims > 1 ? options.y_dim : options.x_dim);
    const sim::RobotSpec robot = hypergp::Model::from_settings(s).robot;
    if (a.elites.empty()) throw InputError("the archive holds no elite (every evaluation failed)", archive_file.string());

    // The best elite of each shown position (dimensions past the fourth collapsed).
    std::map<std::pair<double, double>, double> shown;
    for (const io::ArchiveElite& e : a.elites) {
        const auto c = l.centre_of(a.grid.coordinates(e.cell));
        const auto [it, fresh] = shown.try_emplace({c[0], c[1]}, e.fitness);
        if (!fresh && e.fitness > it->second) it->second = e.fitness;
    }
    detail::ScratchDir scratch;
    std::string text;   // "x y fitness" at the centre of each filled cell (a box each)
    for (const auto& [xy, v] : shown) text += fmt::format("{:g} {:g} {:.10g}\n", xy.first, xy.second, v);
    const fs::path data = scratch.path() / "archive.dat";
    detail::write_file(data, text);

    const io::ArchiveElite* best = a.best();
    const auto mark = l.centre_of(a.grid.coordinates(best->cell));
    const int width = options.width > 0 ? options.width : 900, height = options.height > 0 ? options.height : 760;
    const std::string heading = options.title.empty()
        ? fmt::format("{}: {} of {} cells, best {:.3f} m in cell {} (framed)", run.filename().string(),
                      a.elites.size(), a.grid.cells(), best->fitness, a.grid.cell_name(best->cell))
        : options.title;
    std::string script = detail::terminal_for(out_file, width, height, options.gnuplot, scratch.path()) + "\n";
    script += fmt::format("set output {}\n", detail::quote(out_file.string()));
    script += fmt::format("set lmargin at screen {}\nset rmargin at screen {}\nset bmargin at screen {}\n"
                          "set tmargin at screen {}\n",
                          kHeatmapArea[0], kHeatmapArea[1], kHeatmapArea[2], kHeatmapArea[3]);
    // What each axis's bin numbers mean: the inner dimensions, then the blocks'.
    std::vector<std::string> meaning = {"x: " + bins_label(s, robot, a.grid, l.x_dim)};
    if (dims > 1) meaning.push_back("y: " + bins_label(s, robot, a.grid, l.y_dim));
    if (!l.outer.empty()) meaning.push_back("blocks along x: " + bins_label(s, robot, a.grid, l.outer[0]));
    if (l.outer.size() > 1) meaning.push_back("blocks along y: " + bins_label(s, robot, a.grid, l.outer[1]));
    if (dims > 4) meaning.push_back("dimensions past the fourth are collapsed to their best");
    std::string title = heading;
    for (const std::string& m : meaning) title += "\\n" + m;
    std::string escaped;
    for (char c : title) escaped += c == '"' ? std::string("\\\"") : std::string(1, c);
    script += fmt::format("set title \"{}\" font ',9'\n", escaped);
    script += fmt::format("set xlabel {}\n", detail::quote(fmt::format("bin of dimension {}", l.x_dim + 1)));
    script += dims > 1 ? fmt::format("set ylabel {}\n", detail::quote(fmt::format("bin of dimension {}", l.y_dim + 1)))
                       : "unset ytics\n";
    script += fmt::format("set xrange [-0.5:{:g}]\nset yrange [-0.5:{:g}]\n", l.width() + 0.5, l.height() + 0.5);
    script += bin_tics("x", l.x_bins, l.blocks_x);
    if (dims > 1) script += bin_tics("y", l.y_bins, l.blocks_y);
    auto block_tics = [&](const char* axis, std::size_t dim, int inner, int blocks) {
        std::vector<std::string> tics;
        for (int b = 0; b < blocks; ++b)
            tics.push_back(fmt::format("\"{}\" {:g}", b, b * (inner + 1) + inner / 2.0));
        return fmt::format("set {0}2range [-0.5:{1:g}]\nset {0}2tics ({2}) scale 0\nset {0}2label {3}\n", axis,
                           std::string(axis) == "x" ? l.width() + 0.5 : l.height() + 0.5, fmt::join(tics, ", "),
                           detail::quote(fmt::format("block: bin of dimension {}", dim + 1)));
    };
    if (!l.outer.empty()) script += block_tics("x", l.outer[0], l.x_bins, l.blocks_x);
    if (l.outer.size() > 1) script += block_tics("y", l.outer[1], l.y_bins, l.blocks_y);
    script += "set xtics nomirror\nset ytics nomirror\nset cblabel 'best fitness [m] (eq. 7.1)'\n"
              "set colorbox user origin screen 0.88, screen 0.14 size screen 0.03, screen 0.70\n"
              "set palette rgb 33,13,10\nset style fill solid 1.0 noborder\n";
    // The best cell: a magenta frame (a colour the palette never gives).
    script += fmt::format("set object 1 rect from {:g},{:g} to {:g},{:g} front fillstyle empty border lc rgb "
                          "'#ff00ff' lw 4\n",
                          mark[0] - 0.5, mark[1] - 0.5, mark[0] + 0.5, mark[1] + 0.5);
    script += fmt::format("plot {} using 1:2:(0.5):(0.5):3 with boxxyerror lc palette notitle\n",
                          detail::quote(data.string()));
    detail::render(options.gnuplot, scratch.path(), script, out_file);
}

} // namespace cic::report
