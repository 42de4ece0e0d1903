// `cic plot`: fitness, depth and size per generation from run folders or a study, or a network trace.
#include <fmt/format.h>

#include <iostream>
#include <limits>
#include <memory>
#include <type_traits>

#include "cic/cli/command_guard.hpp"
#include "cic/cli/commands.hpp"
#include "cic/report/archive_plot.hpp"
#include "cic/report/path_plot.hpp"
#include "cic/report/plot.hpp"
#include "cic/core/error.hpp"

namespace cic::cli {
namespace {

struct PlotCommandOptions {
    std::vector<std::string> runs;
    std::string trace;
    std::string out;
    std::string title;
    std::vector<std::string> joints;
    double from = -std::numeric_limits<double>::infinity();
    double to = std::numeric_limits<double>::infinity();
    int width = 0, height = 0;
    bool median = false;
    bool include_unfinished = false;
    bool by_evaluations = false;
    std::vector<std::string> configs;
    bool archive = false;
    bool path = false;
    std::vector<std::string> dims{"1", "2"};
};

// The fields every kind of plot shares; P is PlotOptions or one derived from it.
template <class P>
P plot_options(const PlotCommandOptions& o) {
    P plot;
    plot.title = o.title;
    plot.width = o.width;
    plot.height = o.height;
    if constexpr (std::is_base_of_v<report::StudyPlotOptions, P>) {
        plot.median = o.median;
        plot.include_unfinished = o.include_unfinished;
    }
    return plot;
}

} // namespace

void add_plot_command(Command& app, CommandContext& ctx) {
    auto opts = std::make_shared<PlotCommandOptions>();
    Command cmd = app.subcommand(
        "plot", "Plot run folders (folders named NAME-NNN are grouped by NAME: mean curve, +-1 sd band) or a study "
                "folder from cic sweep (one colour per configuration), with the panels of their search: GP best/mean "
                "fitness, depth and size per generation; gait best so far and each generation's best, IPOP restarts "
                "marked; MAP-Elites QD-score, coverage and best elite per batch (and the archive's heatmap beside). "
                "Or best fitness so far against evaluations of several studies (--by-evaluations), the centre's path "
                "from above (--path), or a trace CSV (--trace)");
    cmd.option("runs", opts->runs,
                    "run folders (each holds stats.csv), or one study folder (holds index.csv), or with "
                    "--by-evaluations several study folders");
    cmd.option("--trace", opts->trace, "plot this trace CSV (from cic trace) instead");
    cmd.option("--out", opts->out, "output .svg or .png (default: plot.svg, or trace.svg with --trace)");
    cmd.option("--title", opts->title, "figure title");
    cmd.option("--joints", opts->joints, "with --trace: only these joints").delimiter(',');
    cmd.option("--from", opts->from, "with --trace: start time, s");
    cmd.option("--to", opts->to, "with --trace: end time, s");
    cmd.option("--width", opts->width, "pixels").positive();
    cmd.option("--height", opts->height, "pixels").positive();
    cmd.flag("--median", opts->median, "with a study: median curves with Q1..Q3 bands (default: mean, +-1 sd)");
    cmd.flag("--include-unfinished", opts->include_unfinished,
                  "with a study: also runs whose status is not done (default: done runs only)");
    cmd.flag("--by-evaluations", opts->by_evaluations,
                  "study folders on one panel: best fitness so far against evaluations used, one curve per "
                  "study and configuration (e.g. HyperGP against CMA-ES at the same budget)");
    cmd.option("--config", opts->configs,
                    "with --by-evaluations: only these configurations (config names of index.csv); every study "
                    "must have them")
        .delimiter(',');
    cmd.flag("--archive", opts->archive,
             "a MAP-Elites run: its archive alone as a heatmap (plain `cic plot RUN` draws it too, as OUT-archive.EXT): "
             "two descriptor dimensions in each block, the next two as a grid of blocks, bins numbered as --cell "
             "takes them, the best cell framed (docs/quality-diversity.md)");
    cmd.flag("--path", opts->path,
             "the centre's path seen from above, with eq. 7.1's preferred axis marked: each run folder's best "
             "individual, or the best run of each configuration of one study, on one figure (replays them)");
    cmd.option("--dims", opts->dims, "with --archive: the two descriptor dimensions inside each block (x, y), from 1")
        .delimiter(',')
        .show_default();
    cmd.on_run([opts, &ctx] {
        run_guarded(ctx, "plot", [&] {
            if (opts->trace.empty() == opts->runs.empty())
                throw InputError("give either run folders or --trace FILE.csv");
            if (opts->path) {
                if (opts->archive || opts->by_evaluations || !opts->trace.empty() || opts->median)
                    throw InputError("--path plots run folders or one study folder on its own (not with --archive, "
                                     "--by-evaluations, --trace or --median)");
                std::vector<std::filesystem::path> dirs(opts->runs.begin(), opts->runs.end());
                if (dirs.size() > 1)
                    for (const auto& dir : dirs)
                        if (report::is_study_folder(dir))
                            throw InputError("a study folder is plotted on its own (give one study, or run folders)",
                                             dir.string());
                const auto paths = report::best_paths(dirs, opts->include_unfinished);
                const std::string out = opts->out.empty() ? "path.svg" : opts->out;
                report::plot_paths(paths, out, plot_options<report::PlotOptions>(*opts));
                if (!ctx.quiet) {
                    for (const auto& p : paths)
                        std::cerr << fmt::format("{}: {:.4f} m along the preferred axis\n", p.label, p.distance);
                    std::cerr << "wrote " << out << '\n';
                }
                return 0;
            }
            if (opts->archive) {
                if (opts->runs.size() != 1 || opts->by_evaluations || !opts->trace.empty())
                    throw InputError("--archive plots one MAP-Elites run folder");
                std::vector<std::size_t> dims;
                for (const std::string& d : opts->dims) {
                    std::size_t used = 0;
                    int v = 0;
                    try {
                        v = std::stoi(d, &used);
                    } catch (const std::exception&) {
                        used = 0;
                    }
                    if (used == 0 || used != d.size() || v < 1)
                        throw InputError("--dims takes two descriptor dimensions, from 1, e.g. --dims 1,2; got '" + d +
                                         "'");
                    dims.push_back(static_cast<std::size_t>(v - 1));
                }
                if (dims.size() != 2) throw InputError("--dims takes two descriptor dimensions, e.g. --dims 1,2");
                auto plot = plot_options<report::ArchivePlotOptions>(*opts);
                plot.x_dim = dims[0];
                plot.y_dim = dims[1];
                const std::string out = opts->out.empty() ? "archive.svg" : opts->out;
                report::plot_archive(opts->runs[0], out, plot);
                if (!ctx.quiet) std::cerr << "wrote " << out << '\n';
                return 0;
            }
            if (opts->by_evaluations && !opts->trace.empty())
                throw InputError("--by-evaluations plots study folders, not a trace");
            if (!opts->trace.empty()) {
                auto plot = plot_options<report::TracePlotOptions>(*opts);
                plot.joints = opts->joints;
                plot.from = opts->from;
                plot.to = opts->to;
                const std::string out = opts->out.empty() ? "trace.svg" : opts->out;
                report::plot_trace(opts->trace, out, plot);
                if (!ctx.quiet) std::cerr << "wrote " << out << '\n';
                return 0;
            }
            if (!opts->configs.empty() && !opts->by_evaluations)
                throw InputError("--config applies with --by-evaluations");
            if (opts->by_evaluations) {
                std::vector<std::filesystem::path> studies;
                for (const auto& dir : opts->runs) {
                    if (!report::is_study_folder(dir))
                        throw InputError("--by-evaluations plots study folders (each holds index.csv from cic sweep)",
                                         dir);
                    studies.emplace_back(dir);
                }
                auto plot = plot_options<report::EvaluationPlotOptions>(*opts);
                plot.configs = opts->configs;
                const std::string out = opts->out.empty() ? "plot.svg" : opts->out;
                report::plot_studies_by_evaluations(studies, out, plot);
                if (!ctx.quiet) std::cerr << "wrote " << out << '\n';
                return 0;
            }
            const bool study = opts->runs.size() == 1 && report::is_study_folder(opts->runs[0]);
            if (!study) {
                for (const auto& dir : opts->runs)
                    if (report::is_study_folder(dir))
                        throw InputError("a study folder is plotted on its own (give one study, or run folders)",
                                         dir);
                if (opts->median || opts->include_unfinished)
                    throw InputError("--median and --include-unfinished apply to a study folder (holds index.csv)");
            } else {
                const auto plot = plot_options<report::StudyPlotOptions>(*opts);
                const std::string out = opts->out.empty() ? "plot.svg" : opts->out;
                report::plot_study(opts->runs[0], out, plot);
                if (!ctx.quiet) {
                    const report::StudyIndex index = report::read_study_index(opts->runs[0]);
                    if (const std::string note = report::runs_missing_note(index); !note.empty())
                        std::cerr << "cic plot: " << note << '\n';
                    for (const auto& g : report::group_study(index, opts->include_unfinished))
                        std::cerr << fmt::format("{}: {} run(s)\n", g.config, g.runs.size());
                    std::cerr << "wrote " << out << '\n';
                }
                return 0;
            }
            const auto plot = plot_options<report::PlotOptions>(*opts);
            std::vector<std::filesystem::path> dirs(opts->runs.begin(), opts->runs.end());
            const std::string out = opts->out.empty() ? "plot.svg" : opts->out;
            report::plot_runs(dirs, out, plot);
            if (!ctx.quiet) {
                for (const auto& g : report::group_runs(dirs))
                    std::cerr << fmt::format("{}: {} run(s)\n", g.label, g.runs.size());
                std::cerr << "wrote " << out << '\n';
            }
            // One MAP-Elites run: its archive too, beside the curves (OUT-archive.EXT).
            if (dirs.size() == 1 && report::is_archive_run(dirs.front())) {
                const std::filesystem::path curves(out);
                const std::filesystem::path heatmap =
                    curves.parent_path() / (curves.stem().string() + "-archive" + curves.extension().string());
                auto archive = plot_options<report::ArchivePlotOptions>(*opts);
                archive.title.clear();
                report::plot_archive(dirs.front(), heatmap, archive);
                if (!ctx.quiet) std::cerr << "wrote " << heatmap.string() << '\n';
            }
            return 0;
        });
    });
}

} // namespace cic::cli
