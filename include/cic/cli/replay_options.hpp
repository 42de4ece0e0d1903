#pragma once
// The options `cic view`, `cic render` and `cic trace` share to pick what to
// replay: a run folder or population file, or a preset robot and controller.
#include "cic/cli/command_line.hpp"
#include "cic/report/preset_replay.hpp"

namespace cic::cli {

// Adds the positional input and --individual, --robot, --middle-legs, --controller, --seconds, --set.
void add_replay_options(Command& command, report::ReplaySource& source);

} // namespace cic::cli
