// `cic report RUN|STUDY --out report.html`: one self-contained page to share a
// run or a study (cic/study/html_report.hpp).
#include <sys/wait.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cic/cli/command_guard.hpp"
#include "cic/cli/commands.hpp"
#include "cic/core/error.hpp"
#include "cic/core/shell_words.hpp"
#include "cic/io/xml.hpp"
#include "cic/run/self_path.hpp"
#include "cic/study/compare_table.hpp"
#include "cic/study/html_report.hpp"

namespace cic::cli {
namespace {

namespace fs = std::filesystem;

#ifdef CIC_HAVE_VIEWER
// The strip through `cic view --screenshot --strip`, in a process of its own:
// it finds an X server (or xvfb-run) as a screenshot does.
std::string strip_by_viewer(const fs::path& run, const std::vector<double>& times, const fs::path& png) {
    std::string at;
    for (double t : times) at += fmt::format("{}{:.3f}", at.empty() ? "" : ",", t);
    const fs::path log = png.string() + ".log";
    const std::string cmd = fmt::format("{} --quiet view {} --screenshot {} --strip {} --width 320 --height 240 > {} 2>&1",
                                        shell_quote(run::self_path()), shell_quote(run.string()), shell_quote(png.string()),
                                        at, shell_quote(log.string()));
    const int rc = std::system(cmd.c_str());
    if (rc == 0) return {};
    std::ifstream in(log);
    std::string first;
    std::getline(in, first);
    return fmt::format("cic view could not draw it (exit {}): {}", WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, first);
}
#endif

} // namespace

void add_report_command(Command& app, CommandContext& ctx) {
    struct Options {
        std::string input;
        std::string out = "report.html";
        std::string metric = "final_best";
        bool include_unfinished = false;
        bool no_strips = false;
    };
    auto opts = std::make_shared<Options>();
    Command cmd = app.subcommand(
        "report", "One self-contained HTML page of a run or a study, to share: provenance, the compare table "
                  "(median, IQR, Mann-Whitney p with Holm, A12 with its interval), the curves, each configuration's "
                  "best gait (a strip, its path from above, the assess verdict), MAP-Elites heatmaps and a table of "
                  "runs. Every figure is inside the file; it fetches nothing and runs no script");
    cmd.option("input", opts->input, "a run folder or a study folder (from cic sweep)").required();
    cmd.option("--out", opts->out, "the HTML file to write (atomically)").show_default();
    cmd.option("--metric", opts->metric, "with a study: the index.csv column the compare table tests").show_default();
    cmd.flag("--include-unfinished", opts->include_unfinished, "with a study: also runs whose status is not done");
    cmd.flag("--no-strips", opts->no_strips, "draw no screenshot strips (they need the viewer and an X server or "
                                             "xvfb-run, and take a few seconds each)");
    cmd.on_run([opts, &ctx] {
        run_guarded(ctx, "report", [&] {
            const fs::path out(opts->out);
            if (out.extension() != ".html" && out.extension() != ".htm")
                throw InputError("--out must name an .html file", opts->out);
            if (!out.parent_path().empty() && !fs::is_directory(out.parent_path()))
                throw InputError("output folder does not exist", out.parent_path().string());
            if (std::find(study::kCompareMetrics.begin(), study::kCompareMetrics.end(), opts->metric) == study::kCompareMetrics.end())
                throw InputError(fmt::format("--metric {}: not one of {}", opts->metric, fmt::join(study::kCompareMetrics, ", ")));
            study::ReportOptions report;
            report.metric = opts->metric;
            report.include_unfinished = opts->include_unfinished;
#ifdef CIC_HAVE_VIEWER
            if (!opts->no_strips) report.strip = strip_by_viewer;
#endif
            if (opts->no_strips) report.no_strip_reason = "none were asked for (--no-strips)";
            const std::string html = study::report_html(opts->input, report);
            io::xml::write_file_atomically(out, html);
            if (!ctx.quiet) std::cerr << fmt::format("wrote {} ({} KB)\n", out.string(), html.size() / 1024);
            return 0;
        });
    });
}

} // namespace cic::cli
