// How a run ended, as its summary.txt says (run_status.hpp).
#include "cic/run/run_status.hpp"

#include <optional>
#include <sstream>
#include <string_view>

namespace cic::run {
namespace {

constexpr std::string_view kStatus = "status: ";
constexpr std::string_view kDone = "done", kInterrupted = "interrupted";
// The stop line of every built-in search's summary, in every phase.
constexpr std::string_view kOlderInterrupted = "stopped: interrupted";

} // namespace

std::string status_line(RunEnd end) {
    return std::string(kStatus) + std::string(end == RunEnd::Done ? kDone : kInterrupted) + "\n";
}

RunEnd run_end_of_summary(const std::string& text) {
    std::istringstream in(text);
    std::optional<RunEnd> said;   // the loop's line comes after the search's text: the last one counts
    bool older_interrupted = false;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(kStatus, 0) == 0)
            said = line.substr(kStatus.size()) == kInterrupted ? RunEnd::Interrupted : RunEnd::Done;
        older_interrupted = older_interrupted || line.rfind(kOlderInterrupted, 0) == 0;
    }
    if (said) return *said;
    return older_interrupted ? RunEnd::Interrupted : RunEnd::Done;
}

} // namespace cic::run
