// MAP-Elites archives as heatmaps (archive_plot.hpp).
#include "cic/report/archive_plot.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/sim/evaluate.hpp"
#include "gnuplot_support.hpp"

namespace cic::app {

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

namespace {

std::string axis_label(const io::Settings& s, const sim::RobotSpec& robot, std::size_t dim) {
    if (s.map_elites.descriptor == sim::Descriptor::Omni) return dim == 0 ? "x displacement [m]" : "y displacement [m]";
    const std::vector<int> feet = sim::branch_ends(robot);
    const int m = feet.at(dim);
    const std::string& name = robot.modules[static_cast<std::size_t>(m)].name;
    return fmt::format("duty factor, foot {}", name.empty() ? "m" + std::to_string(m) : name);
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
    const ArchiveMap m = collapse_archive(a, options.x_dim, a.grid.dimensions() > 1 ? options.y_dim : options.x_dim);
    const sim::RobotSpec robot = hypergp::Model::from_settings(s).robot;

    detail::ScratchDir scratch;
    if (a.elites.empty()) throw InputError("the archive holds no elite (every evaluation failed)", archive_file.string());
    std::string text;   // "x y fitness" at the centre of each filled cell (a box each)
    const double dx = (m.x_hi - m.x_lo) / m.x_bins, dy = (m.y_hi - m.y_lo) / m.y_bins;
    for (int y = 0; y < m.y_bins; ++y)
        for (int x = 0; x < m.x_bins; ++x) {
            const double v = m.best[static_cast<std::size_t>(y) * static_cast<std::size_t>(m.x_bins) +
                                    static_cast<std::size_t>(x)];
            if (!std::isnan(v))
                text += fmt::format("{:.10g} {:.10g} {:.10g}\n", m.x_lo + (x + 0.5) * dx, m.y_lo + (y + 0.5) * dy, v);
        }
    const fs::path data = scratch.path() / "archive.dat";
    detail::write_file(data, text);

    const int width = options.width > 0 ? options.width : 760, height = options.height > 0 ? options.height : 640;
    const io::ArchiveElite* best = a.best();
    std::string heading = options.title.empty()
        ? fmt::format("{}: {} of {} cells, best {:.2f} m", run.filename().string(), a.elites.size(),
                      a.grid.cells(), best ? best->fitness : 0.0)
        : options.title;
    std::string script = detail::terminal_for(out_file, width, height, options.gnuplot, scratch.path()) + "\n";
    script += fmt::format("set output {}\n", detail::quote(out_file.string()));
    script += fmt::format("set title {}\n", detail::quote(heading));
    script += fmt::format("set xlabel {}\n", detail::quote(axis_label(s, robot, m.x_dim)));
    script += a.grid.dimensions() > 1 ? fmt::format("set ylabel {}\n", detail::quote(axis_label(s, robot, m.y_dim)))
                                      : "unset ytics\n";
    script += fmt::format("set xrange [{:.10g}:{:.10g}]\nset yrange [{:.10g}:{:.10g}]\n", m.x_lo, m.x_hi, m.y_lo, m.y_hi);
    script += fmt::format("set xtics {:.10g},{:.10g},{:.10g}\n", m.x_lo, dx, m.x_hi);
    if (a.grid.dimensions() > 1) script += fmt::format("set ytics {:.10g},{:.10g},{:.10g}\n", m.y_lo, dy, m.y_hi);
    script += "set grid front lc rgb '#bbbbbb'\nset cblabel 'best fitness [m] (eq. 7.1), other dimensions "
              "collapsed'\nset palette rgb 33,13,10\nset style fill solid 1.0 noborder\n";
    if (m.x_hi - m.x_lo == m.y_hi - m.y_lo) script += "set size ratio -1\n";
    script += fmt::format("plot {} using 1:2:({:.10g}):({:.10g}):3 with boxxyerror lc palette notitle\n",
                          detail::quote(data.string()), dx / 2, dy / 2);
    detail::render(options.gnuplot, scratch.path(), script, out_file);
}

} // namespace cic::app
