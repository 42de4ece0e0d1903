// `cic plot`: fitness, depth and size per generation from run folders, or a network trace.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "cic/app/command_guard.hpp"
#include "cic/app/commands.hpp"
#include "cic/app/plot.hpp"
#include "cic/core/error.hpp"

namespace cic::app {

void add_plot_command(CLI::App& app, CommandContext& ctx) {
    struct Options {
        std::vector<std::string> runs;
        std::string trace;
        std::string out;
        std::string title;
        std::vector<std::string> joints;
        double from = -std::numeric_limits<double>::infinity();
        double to = std::numeric_limits<double>::infinity();
        int width = 0, height = 0;
    };
    auto opts = std::make_shared<Options>();
    CLI::App* cmd = app.add_subcommand(
        "plot", "Plot best/mean fitness, depth and size per generation of run folders (folders named NAME-NNN "
                "are grouped by NAME: mean curve, +-1 sd band), or a trace CSV with --trace");
    cmd->add_option("runs", opts->runs, "run folders (each holds stats.csv)");
    cmd->add_option("--trace", opts->trace, "plot this trace CSV (from cic trace) instead");
    cmd->add_option("--out", opts->out, "output .svg or .png (default: plot.svg, or trace.svg with --trace)");
    cmd->add_option("--title", opts->title, "figure title");
    cmd->add_option("--joints", opts->joints, "with --trace: only these joints")->delimiter(',');
    cmd->add_option("--from", opts->from, "with --trace: start time, s");
    cmd->add_option("--to", opts->to, "with --trace: end time, s");
    cmd->add_option("--width", opts->width, "pixels")->check(CLI::PositiveNumber);
    cmd->add_option("--height", opts->height, "pixels")->check(CLI::PositiveNumber);
    cmd->callback([opts, &ctx] {
        run_guarded(ctx, "plot", [&] {
            if (opts->trace.empty() == opts->runs.empty())
                throw InputError("give either run folders or --trace FILE.csv");
            if (!opts->trace.empty()) {
                TracePlotOptions plot;
                plot.title = opts->title;
                plot.width = opts->width;
                plot.height = opts->height;
                plot.joints = opts->joints;
                plot.from = opts->from;
                plot.to = opts->to;
                const std::string out = opts->out.empty() ? "trace.svg" : opts->out;
                plot_trace(opts->trace, out, plot);
                if (!ctx.quiet) std::cerr << "wrote " << out << '\n';
                return 0;
            }
            PlotOptions plot;
            plot.title = opts->title;
            plot.width = opts->width;
            plot.height = opts->height;
            std::vector<std::filesystem::path> dirs(opts->runs.begin(), opts->runs.end());
            const std::string out = opts->out.empty() ? "plot.svg" : opts->out;
            plot_runs(dirs, out, plot);
            if (!ctx.quiet) {
                for (const auto& g : group_runs(dirs))
                    std::cerr << fmt::format("{}: {} run(s)\n", g.label, g.runs.size());
                std::cerr << "wrote " << out << '\n';
            }
            return 0;
        });
    });
}

} // namespace cic::app
