// `cic export RUN|STUDY... [--out FILE] [--terms]`: every individual of every
// saved generation as CSV (cic/report/export.hpp, docs/analysis.md).
#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "cic/cli/command_guard.hpp"
#include "cic/cli/commands.hpp"
#include "cic/io/xml.hpp"
#include "cic/report/export.hpp"
#include "cic/report/plot.hpp"

namespace cic::cli {

void add_export_command(Command& app, CommandContext& ctx) {
    struct Options {
        std::vector<std::string> inputs;
        std::string out;
        bool terms = false;
    };
    auto opts = std::make_shared<Options>();
    Command cmd = app.subcommand("export", "Write every individual of every saved generation of run or study folders "
                                           "as CSV: run, config, seed, generation, id, fitness, distance, elevation, "
                                           "depth, size, failed, tree (docs/analysis.md)");
    cmd.option("inputs", opts->inputs, "run folders or study folders (from cic sweep)").required();
    cmd.option("--out", opts->out, "write the CSV here (atomically) instead of stdout");
    cmd.flag("--terms", opts->terms, "fill distance and elevation (eq. 7.1) by replaying each distinct genotype once");
    cmd.on_run([opts, &ctx] {
        run_guarded(ctx, "export", [&] {
            report::ExportRequest r;
            for (const auto& i : opts->inputs) r.inputs.emplace_back(i);
            r.terms = opts->terms;
            if (!ctx.quiet)   // runs an edited sweep file dropped are still on disk: say that they are left out
                for (const auto& i : opts->inputs)
                    if (report::is_study_folder(i))
                        if (const std::string note = report::runs_missing_note(report::read_study_index(i)); !note.empty())
                            std::cerr << "cic export: " << note << '\n';
            r.warn = [](const std::string& line) { std::cerr << "cic export: warning: " << line << '\n'; };
            const std::string csv = report::export_individuals(r);
            if (opts->out.empty()) {
                std::cout << csv;
            } else {
                io::xml::write_file_atomically(opts->out, csv);
                if (!ctx.quiet)
                    std::cerr << fmt::format("wrote {} rows to {}\n", std::count(csv.begin(), csv.end(), '\n') - 1, opts->out);
            }
            return 0;
        });
    });
}

} // namespace cic::cli
