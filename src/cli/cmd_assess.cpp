// `cic assess RUN...`: is each run's best individual walking? One CSV row per
// input (gait_assessment.hpp), to stdout or --out.
#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <sstream>

#include "cic/cli/command_guard.hpp"
#include "cic/cli/commands.hpp"
#include "cic/report/gait_assessment.hpp"
#include "cic/report/plot.hpp"
#include "cic/io/xml.hpp"

namespace cic::cli {

void add_assess_command(Command& app, CommandContext& ctx) {
    struct Options {
        std::vector<std::string> inputs;
        std::string out;
        double shaking_above = report::kShakingAboveHz;
        std::string cell;
    };
    auto opts = std::make_shared<Options>();
    Command cmd = app.subcommand(
        "assess", "Replay the best individual of each run folder (or population file) and say whether it walks: "
                  "dominant command frequency, centre height, flipped, shaking (thesis 7.3.2.1), and the raw eq. 7.1 "
                  "fitness without any penalty. CSV, one row per input");
    cmd.option("inputs", opts->inputs, "run folders, population XML files, or study folders (their done runs)").required();
    cmd.option("--cell", opts->cell,
               "in MAP-Elites runs, assess this cell's elite instead of the best: I,J,... or the cell's number");
    cmd.option("--out", opts->out, "write the CSV here (atomically) instead of stdout");
    cmd.option("--shaking-above", opts->shaking_above, "dominant command frequency, Hz, above which a gait is "
                                                            "marked shaking")
        .show_default()
        .positive();
    cmd.on_run([opts, &ctx] {
        run_guarded(ctx, "assess", [&] {
            std::ostringstream csv;
            csv << "input,fitness,dominant_hz,mean_height,min_height,final_up,flipped,shaking,raw_fitness,distance,"
                   "elevation,verdict,duty_factors\n";
            // A study folder (index.csv) stands for its finished runs, as in plot, export and compare.
            const std::vector<std::string> inputs = report::finished_runs_of(opts->inputs);
            for (const std::string& input : inputs) {
                const auto items = report::replay(input, opts->cell.empty() ? "best" : "cell:" + opts->cell, 1, 10.0, true);
                if (const auto& item = items.at(0); item.replayed_fitness != item.stored_fitness)
                    std::cerr << fmt::format("cic assess: warning: {}: {}'s stored fitness {:.17g} does not replay: "
                                             "the replay gives {:.17g} (cic verify RUN checks every value)\n",
                                             input, item.label, item.stored_fitness, item.replayed_fitness);
                const report::GaitAssessment a = report::assess_gait(items.at(0), opts->shaking_above);
                std::string duty;   // "foot:fraction" per foot, space-separated
                for (std::size_t f = 0; f < a.foot_names.size(); ++f)
                    duty += fmt::format("{}{}:{:.3f}", f ? " " : "", a.foot_names[f], a.duty_factors[f]);
                csv << fmt::format("{},{:.17g},{:.4f},{:.4f},{:.4f},{:.4f},{},{},{:.17g},{:.4f},{:.4f},{},{}\n", input,
                                   a.fitness, a.dominant_hz, a.mean_height, a.min_height, a.final_up, a.flipped ? 1 : 0,
                                   a.shaking ? 1 : 0, a.raw_fitness, a.distance, a.elevation, a.verdict, duty);
            }
            if (opts->out.empty()) {
                std::cout << csv.str();
            } else {
                io::xml::write_file_atomically(opts->out, csv.str());
                if (!ctx.quiet) std::cerr << fmt::format("assessed {} gaits; wrote {}\n", inputs.size(), opts->out);
            }
            return 0;
        });
    });
}

} // namespace cic::cli
