#pragma once
// What `cic sweep` does with a plan (cic/study/sweep.hpp): check it, list it,
// run it here N tasks at a time, or write it as a Slurm job array.
#include <string>
#include <vector>

#include "cic/study/sweep.hpp"

namespace cic::study {

// The tasks of the named configurations (--config), in plan order; every task
// when `names` is empty. Throws cic::InputError for an unknown name, listing the
// sweep's names.
std::vector<SweepTask> selected_tasks(const SweepPlan& plan, const std::vector<std::string>& names);

// Loads and checks every configuration's settings (seeds change no input),
// before anything is written. Throws cic::InputError naming the configuration.
void check_every_configuration(const SweepPlan& plan);

// Prints each task's status, run key and command; runs nothing. Returns 0.
// Text: for people, with the plan's head and each mismatched key. Csv: for
// programs, index_text(..., IndexColumns::WithTaskAndCommand) and nothing else.
enum class DryRunFormat { Text, Csv };
int dry_run(const SweepPlan& plan, const std::vector<SweepTask>& tasks, int workers,
            DryRunFormat format = DryRunFormat::Text);

// What a cluster asks of a job, beside what cic sets itself (array, CPUs,
// output, requeue, the SIGTERM before the time limit). Empty: not written.
struct SlurmOptions {
    std::string partition;              // --partition
    std::string time;                   // --time: minutes, MM:SS, HH:MM:SS, D-HH[:MM[:SS]]
    std::string mem;                    // --mem: N with an optional K, M, G or T
    std::string account;                // --account
    std::vector<std::string> extra;     // more #SBATCH options, e.g. --qos=long
};
// Throws cic::InputError naming the option and what it takes.
void check_slurm_options(const SlurmOptions& o);

// Writes STUDY/slurm.sh, a job array of `tasks` (their plan indices), at most
// `jobs` at once (the array throttle %N), and the index. Returns 0.
int write_slurm_script(const SweepPlan& plan, const std::vector<SweepTask>& tasks, int jobs, int workers,
                       const SlurmOptions& slurm = {});

// A study's progress at a glance: how many runs are done, running, pending,
// interrupted or failed, and an estimate of the time left from the finished
// runs' times, `jobs` at a time. Works on a local or a Slurm study. Returns 0.
int print_status(const SweepPlan& plan, const std::vector<SweepTask>& tasks, int jobs);

// Runs the tasks not done yet, `jobs` at a time, as child processes (each one
// `cic sweep FILE --task I`), rebuilding index.csv as they finish. SIGINT and
// SIGTERM stop them at their next checkpoint. Returns 0, 1 (a task failed),
// 130 or 143.
int run_locally(const SweepPlan& plan, const std::vector<SweepTask>& tasks, int jobs, int workers, bool quiet);

} // namespace cic::study
