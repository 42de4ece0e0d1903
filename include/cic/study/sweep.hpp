#pragma once
// Studies: a sweep file names a base settings file, the keys to vary (a full
// grid) and/or named variants, and how many repeats with which seeds. Every
// (configuration, seed) is a task with its own run folder under one study
// folder; a task is resumable in place, so a sweep can be interrupted, rerun,
// or run as a Slurm job array with the same command (docs/cluster.md).
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "cic/io/settings.hpp"

namespace cic::study {

// How each repeat's seed follows from <repeats firstSeed="F" count="R">:
// same: repeat r of every configuration has seed F + r (paired: configurations
// meet the same random starts); distinct: configuration c gets F + c*R + r.
enum class SeedRule { Same, Distinct };

struct SweepConfig {
    std::string name;                                        // folder-safe, unique
    std::vector<std::pair<std::string, std::string>> varied; // Section.key -> value (grid, then "variant")
    std::vector<std::string> overrides;                      // Section.key=value for this configuration
    int line = 0;   // where the sweep file defines it (its <variant>, else its <grid>, else <sweep>)
};

struct SweepTask {
    std::size_t index = 0;        // 0..tasks-1: seed-major, so a partial study covers every configuration
    std::size_t config = 0;
    int repeat = 0;
    std::uint64_t seed = 0;
    std::filesystem::path run_dir;   // relative to the study folder: runs/CONFIG/sSEED
};

struct SweepPlan {
    std::filesystem::path file;                // the sweep file (absolute)
    std::string name;
    std::filesystem::path base;                // base settings file (absolute)
    std::string base_xml;                      // its text when the plan was read
    std::vector<std::string> common;           // overrides for every run
    std::vector<std::string> varied_keys;      // index.csv columns between config and seed
    std::vector<SweepConfig> configs;
    int repeats = 1;
    std::uint64_t first_seed = 1;
    SeedRule rule = SeedRule::Same;
    std::filesystem::path study;               // output folder (absolute)
    // Optional run store shared by studies (<store>, relative to the study
    // folder): a task runs in STORE/KEY, KEY fingerprinting its settings and
    // seed, and its runs/CONFIG/sSEED is a link to it. Studies that share a
    // configuration then run it once (docs/cluster.md, "Run store").
    std::filesystem::path store;

    std::vector<SweepTask> tasks() const;
    // Every --set of a task: common, the configuration's, then its seed.
    std::vector<std::string> overrides(const SweepTask& task) const;
    // The command a task's run is: "cic --settings BASE --set K=V ..." (as the dry run shows it).
    std::string command_line(const SweepTask& task) const;
    // The settings a task asks for: the base as read with the plan (an edit of
    // the base file while a task runs changes neither that run nor what its
    // index says of it), then overrides(task), then `extra`.
    io::Settings settings(const SweepTask& task, const std::vector<std::string>& extra = {}) const;
};

// Reads and checks a sweep file (format in docs/cluster.md, schema
// settings/cic-sweep.xsd); `output` (if not empty) replaces its <output>.
// Throws cic::InputError with file and line.
SweepPlan read_sweep_file(const std::filesystem::path& file, const std::filesystem::path& output = {});
// The same on a sweep file's text; `file` names it and anchors its relative paths.
SweepPlan parse_sweep(std::string_view text, const std::filesystem::path& file,
                      const std::filesystem::path& output = {});

// Where a task stands, from its run folder alone. Mismatched: the study's own
// run folder (not a store link) holds a run of other settings than the sweep
// now asks of the task (an edited sweep or base file); never run over, never
// counted as done.
// Extend: a run of the study whose budget the sweep has since raised (only the
// budget differs, and it grows): the task goes on from its checkpoint.
enum class TaskStatus { Pending, Running, Done, Interrupted, Failed, Mismatched, Extend };
std::string to_string(TaskStatus s);

struct TaskState {
    TaskStatus status = TaskStatus::Pending;
    std::string final_best;       // last generation's best, as written in stats.csv
    std::string best_ever;        // the best of every generation (stats.csv's best column, its maximum)
    int generations = 0;
    long evaluations = 0;
    double wall_seconds = 0;      // summed over the sessions that ran it
    std::vector<std::string> mismatch;   // Mismatched: each key that differs, ran vs asked
};
// Throws cic::InputError naming every mismatched task of the study, the keys that
// differ and what to do, before anything of the study is written or run.
void refuse_mismatched_runs(const SweepPlan& plan);
TaskState task_state(const SweepPlan& plan, const SweepTask& task);

// Run folders under STUDY/runs/CONFIG/sSEED that hold a run (settings.xml) but
// are no task of the plan (a configuration or seed dropped from an edited
// sweep file): index.csv and `cic export` leave them out, so the sweep says so.
std::vector<std::filesystem::path> runs_outside_the_plan(const SweepPlan& plan);

// What a task computes, as 16 hex digits: the FNV-1a of cic's version and the
// task's settings that differ from the defaults (without the run's name, output
// folder and worker count, which change no result; a file key by its bytes, not
// its path). The run store's KEY; in index.csv and --dry-run, so that a record of
// a run kept elsewhere (a ledger) can tell whether the sweep still asks for it.
std::string run_key(const SweepPlan& plan, const SweepTask& task);

// Rewrites STUDY/index.csv (atomically, under a lock shared by every task):
// run_dir,config,<varied keys>,seed,status,final_best,generations,evaluations,wall_seconds,best_ever,commit,run_key
// (commit: the cic build of the run's last session, from its run.log; provenance.hpp;
// run_key: the settings the sweep asks of the task, run_key above)
void write_index(const SweepPlan& plan);

// index.csv's text for `tasks`, as write_index writes it. WithTaskAndCommand
// (`cic sweep --dry-run --csv`) adds a first column `task` (the plan index that
// --task takes) and a last column `command` (the run's cic command line, shell
// quoted, done or not): one format for every program that reads a study's runs.
enum class IndexColumns { Index, WithTaskAndCommand };
std::string index_text(const SweepPlan& plan, const std::vector<SweepTask>& tasks,
                       IndexColumns columns = IndexColumns::Index);

// The run store folder of a task (plan.store must be set): STORE/KEY, KEY its
// run_key; or the store folder whose settings.xml has that fingerprint, when an
// older cic named it otherwise.
std::filesystem::path store_dir(const SweepPlan& plan, const SweepTask& task);

// With a store: makes every task's runs/CONFIG/sSEED a relative link to its
// store folder, unless the study already has a real folder there (a study
// begun without a store keeps its runs). Without a store: nothing.
// StoredRunsOnly (for --index-only, which runs nothing): links only the tasks
// whose store folder holds a run, and makes no folder in the store.
enum class StoreLinks { Every, StoredRunsOnly };
void link_to_store(const SweepPlan& plan, StoreLinks which = StoreLinks::Every);

// Runs one task in its folder: skipped when done, resumed in place from its
// checkpoint when one exists, started afresh otherwise. `workers` > 0 sets
// Experiment.workers. Returns cic's exit code (0, 1, 2, 130, 143); a task
// already running elsewhere (its folder is locked) returns 0 with a note.
int run_task(const SweepPlan& plan, const SweepTask& task, int workers, bool quiet,
             const std::string& executable);

} // namespace cic::study
