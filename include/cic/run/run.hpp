#pragma once
// The main job: run the experiment the settings describe.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "cic/io/archive_xml.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings.hpp"

namespace cic::app {

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
    std::optional<io::PopulationFile> resume;   // populationXmlLoadFrom, parsed and checked
    std::optional<io::GaitFile> gait_resume;    // the same, for the gait experiment
    std::optional<io::ArchiveFile> archive_resume;   // the same, for MAP-Elites (MapElites.enabled)
    // What the run says about the checkpoint it goes on from: a file without an
    // <origin> (believed), and a file made with other search settings (its
    // origin matched, so its fitness values hold). Empty when nothing to say;
    // a resume in place, which allows only a budget change, clears the second
    // and says the budget instead.
    std::string origin_note;
    std::string search_note;
};

// Checks every input of a run: the experiment's own (robot file and its
// joints, dataset; experiments::check_inputs) and the population to resume
// from (parsed completely, its values checked, its origin — robot geometry,
// simulator, controller, genotype, descriptor — the settings' own, and its
// contents checked against the settings). Throws cic::InputError with file and
// line; writes nothing.
// `cic settings FILE` runs the same checks.
PreparedRun prepare_run(io::Settings settings);

// Returns an exit code: 0 done, 1 failure, 130 interrupted by SIGINT, 143 by
// SIGTERM (the checkpoint is written first; a second signal ends it at once).
int run_experiment(PreparedRun run, const RunOptions& options);

} // namespace cic::app
