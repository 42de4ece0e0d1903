#pragma once
// The main job: run the experiment the settings describe.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include <memory>

#include "cic/io/settings.hpp"
#include "cic/search/search.hpp"

namespace cic::run {

struct RunOptions {
    std::filesystem::path run_dir;   // already created, empty; effective settings are written here
    bool quiet = false;
    bool verbose = false;
    std::string worker_executable;   // path of the cic binary, for worker processes
    // Resuming in the run's own folder (a sweep task): stats.csv keeps its rows up
    // to the checkpoint's generation and grows from there, instead of starting anew.
    bool continue_in_place = false;
    // What an interrupted run tells the user to type to go on; empty: `cic resume RUN_DIR`.
    std::string resume_command;
};

// Everything a run reads, loaded and checked before its folder exists.
struct PreparedRun {
    io::Settings settings;
    // The search the settings pick (Experiment.search, search/search.hpp).
    const search::SearchKind* search = nullptr;
    // populationXmlLoadFrom, read by the search's own strict reader and checked;
    // its notes (origin_note, search_note) are said when the run starts. A
    // resume in place, which allows only a budget change, clears search_note
    // and says the budget instead.
    std::unique_ptr<search::Checkpoint> resume;
};

// Checks every input of a run: the experiment's own (robot file and its
// joints, dataset; experiments::check_inputs), the search the settings pick
// (Experiment.search) and the checkpoint to resume from (read by that search's
// strict reader: parsed completely, its values checked, its origin — robot
// geometry, simulator, controller, genotype, descriptor — the settings' own,
// and its contents checked against the settings). Throws cic::InputError with
// file and line; writes nothing.
// `cic settings FILE` runs the same checks.
PreparedRun prepare_run(io::Settings settings);

// The one run loop, for every search: start, then stop rule, checkpoint and
// step until the search stops; stats.csv, run.log, the progress line, stop
// signals and summary.txt around it. Returns an exit code: 0 done, 1 failure,
// 130 interrupted by SIGINT, 143 by SIGTERM (the checkpoint is written first;
// a second signal ends it at once).
int run_experiment(PreparedRun run, const RunOptions& options);

} // namespace cic::run
