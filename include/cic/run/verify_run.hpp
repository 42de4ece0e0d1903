#pragma once
// `cic verify RUN`: replays everything the run's last checkpoint holds (every
// individual, every elite, a gait run's champion and candidates, a
// Switch-HybrID hand-over) and checks the checkpoint against its folder
// (run_history.hpp), saying each disagreement on its own line.
#include <filesystem>

namespace cic::run {

// Returns 0 when every stored value replays bit for bit and the folder agrees
// with itself, 1 otherwise. Throws cic::InputError (exit 2) for a folder that
// holds no run or no checkpoint, or a checkpoint that cannot be read.
int verify_run(const std::filesystem::path& run_dir, bool quiet);

} // namespace cic::run
