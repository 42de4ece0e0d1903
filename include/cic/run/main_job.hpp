#pragma once
// The main job, `cic --settings FILE [--set K=V]... [--seed N | --seeds A-B]`:
// one run folder per seed (OUTPUT/NAME-NNN with settings.xml and run.log),
// every seed's input checked before the first run writes anything.
#include <string>
#include <vector>

namespace cic::run {

struct MainJob {
    std::string settings_file;        // as found (cic/run/settings_lookup.hpp)
    std::vector<std::string> sets;    // Section.key=value
    std::string seed;                 // kept as text: the settings table checks it
    std::string seeds;                // "A-B" or "A,B,C": one run per seed, one after another
    std::string output;               // Experiment.outputDirectory, when not empty
    std::string command_line;         // for run.log
    bool quiet = false, verbose = false;
};

// Returns cic's exit code (0, 1, 130, 143; an interrupted run stops the seeds
// after it). Throws cic::InputError for bad input, before anything is written.
int run_main_job(const MainJob& job);

} // namespace cic::run
