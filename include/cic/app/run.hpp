#pragma once
// The main job: run the experiment the settings describe.
#include <filesystem>
#include <functional>
#include <string>

#include "cic/io/settings.hpp"

namespace cic::app {

struct RunOptions {
    std::filesystem::path run_dir;   // already created, empty; effective settings are written here
    bool quiet = false;
    bool verbose = false;
    std::string worker_executable;   // path of the cic binary, for worker processes
};

// Returns an exit code (0 success, 1 failure). Throws cic::InputError on bad input
// discovered late (e.g. an incompatible population file).
int run_experiment(const io::Settings& settings, const RunOptions& options);

} // namespace cic::app
