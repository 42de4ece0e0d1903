// `cic trace`: per control step raw outputs, commands, angles and centre of a replayed individual.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "cic/cli/command_guard.hpp"
#include "cic/cli/commands.hpp"
#include "cic/report/plot.hpp"
#include "cic/cli/replay_options.hpp"
#include "cic/report/trace_csv.hpp"

namespace cic::cli {

void add_trace_command(Command& app, CommandContext& ctx) {
    struct Options {
        report::ReplaySource source;
        std::string out = "trace.csv";
        std::string plot;
    };
    auto opts = std::make_shared<Options>();
    Command cmd = app.subcommand(
        "trace", "Write the network trace of an individual's replay as CSV "
                 "(t, out_<joint>, cmd_<joint>, angle_<joint>, cx, cy, cz)");
    add_replay_options(cmd, opts->source);
    cmd.option("--out", opts->out, "CSV file to write").show_default();
    cmd.option("--plot", opts->plot, "also draw it into this .svg or .png (like cic plot --trace)");
    cmd.on_run([opts, &ctx] {
        run_guarded(ctx, "trace", [&] {
            const auto items = report::load_replay(opts->source, 1, 0.0, true);
            const report::ReplayItem& item = items.at(0);
            if (item.trace.empty()) throw std::runtime_error("the replay recorded no trace rows");
            // Without raw outputs (a controller that does not report them) the commands stand in.
            std::vector<std::vector<double>> raw = item.raw_outputs;
            if (raw.empty())
                for (const auto& row : item.trace) raw.push_back(row.desired);
            report::write_trace_csv(opts->out, report::make_trace(item.trace, raw), report::joint_names_of(item));
            if (!ctx.quiet)
                std::cerr << fmt::format("{}: fitness {:.6g}; wrote {} rows to {}\n", item.label,
                                         item.replayed_fitness, item.trace.size(), opts->out);
            if (!opts->plot.empty()) {
                report::TracePlotOptions plot;
                plot.title = item.label;
                report::plot_trace(opts->out, opts->plot, plot);
                if (!ctx.quiet) std::cerr << "plotted " << opts->plot << '\n';
            }
            return 0;
        });
    });
}

} // namespace cic::cli
