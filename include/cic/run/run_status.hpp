#pragma once
// How a run ended, as its summary.txt says. The run loop writes the line
// itself ("status: done" or "status: interrupted"), from its own stop, so a
// search's summary text cannot make an interrupted run read as finished (a
// Switch-HybrID run stopped in its gait phase once did: its summary opens with
// the HyperGP phase's). Summaries of cic before the line are read by their
// "stopped: interrupted" lines, wherever they stand.
#include <string>

namespace cic::run {

enum class RunEnd { Done, Interrupted };

// The summary line the run loop writes: "status: done\n" or "status: interrupted\n".
std::string status_line(RunEnd end);

// How the run whose summary.txt says TEXT ended.
RunEnd run_end_of_summary(const std::string& text);

} // namespace cic::run
