// `cic compare STUDY`: per configuration summaries of a study and pairwise
// Mann-Whitney U tests with A12 effect sizes and Holm's correction, as Markdown
// (and CSV with --out). The tables: cic/study/compare_table.hpp.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "cic/cli/command_guard.hpp"
#include "cic/cli/commands.hpp"
#include "cic/core/error.hpp"
#include "cic/io/xml.hpp"
#include "cic/study/compare_table.hpp"

namespace cic::cli {
namespace {

namespace fs = std::filesystem;

struct CompareOptions : study::CompareRequest {
    std::string study;
    std::string out;
};

int run_compare(const CompareOptions& o, const CommandContext& ctx) {
    if (!o.out.empty()) {   // before anything is read
        const fs::path out_dir = fs::path(o.out).parent_path();
        if (!out_dir.empty() && !fs::is_directory(out_dir))
            throw InputError("output folder does not exist", out_dir.string());
    }
    const study::CompareTables tables = study::compare_study(o.study, o);
    std::cout << tables.markdown << std::flush;
    if (!o.out.empty()) {
        io::xml::write_file_atomically(o.out + ".md", tables.markdown);
        io::xml::write_file_atomically(o.out + "-configs.csv", tables.configs_csv);
        io::xml::write_file_atomically(o.out + "-pairs.csv", tables.pairs_csv);
        if (!ctx.quiet) std::cerr << fmt::format("wrote {0}.md, {0}-configs.csv, {0}-pairs.csv\n", o.out);
    }
    return 0;
}

} // namespace

void add_compare_command(Command& app, CommandContext& ctx) {
    auto opts = std::make_shared<CompareOptions>();
    Command cmd = app.subcommand(
        "compare", "Compare the configurations of a study folder (from cic sweep): per configuration n, "
                   "mean +- sd, median and IQR of the final best fitness, time to a threshold; per pair "
                   "Mann-Whitney U, Vargha-Delaney A12 and Holm-adjusted p (docs/statistics.md). Markdown on stdout");
    cmd.option("study", opts->study, "study folder (holds index.csv)").required();
    Option threshold =
        cmd.option("--threshold", opts->threshold,
                        "report the generation and evaluations at which each run's best first reached X (best >= X)");
    cmd.option("--metric", opts->metric,
                    "index.csv column to summarise and test: final_best, best_ever (the best of every generation; the "
                    "fair measure when the last generation can lose the best), generations, evaluations, wall_seconds")
        .show_default();
    cmd.option("--out", opts->out, "also write PREFIX.md, PREFIX-configs.csv and PREFIX-pairs.csv");
    cmd.option("--alpha", opts->alpha, "significance level for the Holm-adjusted p-values")
        .show_default();
    cmd.flag("--include-unfinished", opts->include_unfinished,
                  "also use runs whose status is not done (pending, running, interrupted, failed)");
    cmd.on_run([opts, threshold, &ctx] {
        run_guarded(ctx, "compare", [&] {
            opts->has_threshold = threshold.count() > 0;
            return run_compare(*opts, ctx);
        });
    });
}

} // namespace cic::cli
