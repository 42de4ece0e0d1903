#pragma once
// The running cic binary, for child processes and for the commands cic writes.
#include <string>

namespace cic::run {

// Its file, for messages, dry runs and Slurm scripts: /proc/self/exe resolved
// (without the " (deleted)" Linux adds once the file was replaced), else
// argv0 made absolute, else "cic".
std::string self_path(const char* argv0 = nullptr);

// What to exec for worker processes and sweep tasks: /proc/self/exe, i.e. the
// very binary that is running even if its file has been replaced meanwhile
// (cic reinstalled during a study), so that one run or study never mixes two
// builds; self_path() where /proc is missing.
std::string self_exec_path();

} // namespace cic::run
