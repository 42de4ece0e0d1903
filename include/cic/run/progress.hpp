#pragma once
// The run's voice on the console: a live progress line per generation on a
// terminal, plain log lines otherwise. The evolution loop knows nothing of it;
// it emits a gp::GenerationRecord, the run turns it into a ProgressLine and
// this class prints it.
#include <iosfwd>
#include <string>
#include <string_view>

#include "cic/search/progress_line.hpp"

namespace cic::run {

using search::ProgressLine;

enum class Verbosity { Quiet, Normal, Verbose };

// "45s", "3m07s", "2h05m", "?" for a negative or non-finite value.
std::string format_duration(double seconds);

// One line of text for a record, without any terminal control characters.
std::string format_line(const ProgressLine& line);

class ProgressPrinter {
public:
    // live: rewrite one line in place (a terminal); otherwise one line per record.
    ProgressPrinter(std::ostream& out, bool live, Verbosity verbosity);

    // Prints to stderr, live when stderr is a terminal.
    static ProgressPrinter for_stderr(Verbosity verbosity);

    // Callback-friendly: printer(record). Quiet prints nothing. Verbose keeps
    // every generation's line on a terminal instead of rewriting one.
    void operator()(const ProgressLine& line);

    // A log line (e.g. "checkpoint written"); on a terminal it goes above the
    // live line, which is redrawn below it. Shown unless quiet; `detail` lines only when verbose.
    void message(std::string_view text, bool detail = false);

    // Ends the live line (a newline) if one is showing. Called by the destructor.
    void finish();

    ~ProgressPrinter();
    ProgressPrinter(ProgressPrinter&& other) noexcept;
    ProgressPrinter(const ProgressPrinter&) = delete;
    ProgressPrinter& operator=(const ProgressPrinter&) = delete;
    ProgressPrinter& operator=(ProgressPrinter&&) = delete;

private:
    std::ostream* out_;
    bool live_;
    Verbosity verbosity_;
    bool line_open_ = false;
    std::string last_line_;   // the live line, redrawn after a message
};

} // namespace cic::run
