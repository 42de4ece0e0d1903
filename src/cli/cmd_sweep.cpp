// `cic sweep FILE`: runs every (configuration, seed) of a sweep file as its own
// run folder under one study folder, N at a time; or writes a Slurm job array
// that runs the same resumable command per task (docs/cluster.md).
#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "cic/cli/command_guard.hpp"
#include "cic/cli/commands.hpp"
#include "cic/core/parallel_for.hpp"
#include "cic/io/xml.hpp"
#include "cic/run/self_path.hpp"
#include "cic/study/sweep.hpp"
#include "cic/study/sweep_runner.hpp"

namespace cic::cli {
namespace {

namespace fs = std::filesystem;

struct SweepOptions {
    std::string file;
    std::string output;
    int jobs = 1;
    int workers = 0;      // 0: cores / jobs
    long task = -1;       // >= 0: run this one task (Slurm array tasks, and the local runner's children)
    bool dry_run = false;
    bool csv = false;     // with --dry-run: the listing as CSV
    bool slurm = false;
    bool index_only = false;
    bool status = false;
    study::SlurmOptions cluster;        // --slurm-partition, ...
    std::vector<std::string> configs;   // --config: only these configurations (empty: all)
};

} // namespace

void add_sweep_command(Command& app, CommandContext& ctx) {
    auto o = std::make_shared<SweepOptions>();
    Command cmd = app.subcommand(
        "sweep", "Run a study: every (configuration, seed) of a sweep file in its own run folder, N at a time, "
                 "resumable; or write a Slurm job array for it");
    cmd.option("file", o->file, "sweep file (docs/cluster.md)").required();
    cmd.option("--jobs,-j", o->jobs, "runs at the same time (with --slurm: array tasks at once)")
        .show_default()
        .range(1, 4096);
    cmd.option("--workers", o->workers, "worker processes per run (default: cores / jobs, at least 1)")
        .range(0, 4096);
    cmd.option("--output", o->output, "study folder (default: the sweep file's <output>, else runs/NAME)");
    cmd.flag("--dry-run", o->dry_run, "list every run with its status, run key (key=) and command; run nothing");
    cmd.flag("--csv", o->csv,
             "with --dry-run: print the listing as CSV, index.csv's columns with `task` first and `command` last "
             "(for scripts; a mismatched run's differing keys are in the plain listing)");
    cmd.flag("--index-only", o->index_only,
                  "rewrite STUDY/index.csv from the run folders, linking runs already stored; run nothing");
    cmd.flag("--slurm", o->slurm, "write STUDY/slurm.sh, a job array with one task per run");
    cmd.option("--slurm-partition", o->cluster.partition, "with --slurm: the partition (#SBATCH --partition)");
    cmd.option("--slurm-time", o->cluster.time, "with --slurm: each task's time limit (minutes, HH:MM:SS, D-HH:MM)");
    cmd.option("--slurm-mem", o->cluster.mem, "with --slurm: memory per task's node (e.g. 4G)");
    cmd.option("--slurm-account", o->cluster.account, "with --slurm: the account to charge");
    cmd.option("--sbatch", o->cluster.extra, "with --slurm: one more #SBATCH option (repeatable), e.g. --qos=long");
    cmd.flag("--status", o->status,
             "show how many runs are done, running, pending and failed, and the time left (--jobs at a time)");
    cmd.option("--config", o->configs,
               "only this configuration's runs (repeatable; with the local runner, --dry-run and --slurm)");
    cmd.option("--task", o->task, "run only task I (0-based), resumably: what each array task runs")
        .range(0L, 100000000L);
    cmd.on_run([o, &ctx] {
        run_guarded(ctx, "sweep", [&] {
            if (o->csv && !o->dry_run) throw InputError("--csv goes with --dry-run (the listing it prints as CSV)");
            const study::SweepPlan plan = study::read_sweep_file(o->file, o->output);
            const int workers = o->workers > 0 ? o->workers : std::max(1, hardware_threads() / o->jobs);
            if (o->task >= 0) {
                if (!o->configs.empty())
                    throw InputError("--config and --task: a task is one run already; give one of them",
                                     plan.file.string());
                const auto tasks = plan.tasks();
                if (static_cast<std::size_t>(o->task) >= tasks.size())
                    throw InputError(fmt::format("--task {}: the sweep has tasks 0..{}", o->task, tasks.size() - 1),
                                     plan.file.string());
                return study::run_task(plan, tasks[static_cast<std::size_t>(o->task)], workers, ctx.quiet, run::self_exec_path());
            }
            const std::vector<study::SweepTask> tasks = study::selected_tasks(plan, o->configs);
            const bool cluster_options = !o->cluster.partition.empty() || !o->cluster.time.empty() ||
                                         !o->cluster.mem.empty() || !o->cluster.account.empty() ||
                                         !o->cluster.extra.empty();
            if (cluster_options && !o->slurm)
                throw InputError("--slurm-partition, --slurm-time, --slurm-mem, --slurm-account and --sbatch go with "
                                 "--slurm");
            study::check_slurm_options(o->cluster);
            if (const auto outside = study::runs_outside_the_plan(plan); !outside.empty()) {
                // Still on disk, but no task of the sweep file now: index.csv and export leave them out.
                std::string list;
                for (std::size_t i = 0; i < outside.size() && i < 5; ++i) list += (i ? ", " : "") + outside[i].string();
                if (outside.size() > 5) list += fmt::format(" and {} more", outside.size() - 5);
                std::cerr << fmt::format("cic sweep: note: {} run folder{} of the study belong{} to no task of {} (a "
                                         "configuration or seed left the sweep file?); index.csv, plot and export "
                                         "leave {} out: {}\n",
                                         outside.size(), outside.size() == 1 ? "" : "s", outside.size() == 1 ? "s" : "",
                                         plan.file.string(), outside.size() == 1 ? "it" : "them", list);
            }
            if (o->status) return study::print_status(plan, tasks, o->jobs);
            study::check_every_configuration(plan);
            if (o->dry_run)
                return study::dry_run(plan, tasks, workers, o->csv ? study::DryRunFormat::Csv : study::DryRunFormat::Text);
            if (o->index_only) {   // for summaries: the runs as they are, nothing run
                fs::create_directories(plan.study);
                study::link_to_store(plan, study::StoreLinks::StoredRunsOnly);
                study::write_index(plan);
                return 0;
            }
            study::refuse_mismatched_runs(plan);   // before anything of the study is written
            fs::create_directories(plan.study);
            study::link_to_store(plan);
            io::xml::write_file_atomically(plan.study / "sweep.xml", io::xml::Document::load_file(plan.file).to_string());
            if (o->slurm) return study::write_slurm_script(plan, tasks, o->jobs, workers, o->cluster);
            study::write_index(plan);
            return study::run_locally(plan, tasks, o->jobs, workers, ctx.quiet);
        });
    });
}

} // namespace cic::cli
