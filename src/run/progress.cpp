#include "cic/run/progress.hpp"

#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace cic::run {

std::string format_duration(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0) return "?";
    const long s = std::lround(seconds);
    if (s < 60) return fmt::format("{}s", s);
    if (s < 3600) return fmt::format("{}m{:02}s", s / 60, s % 60);
    return fmt::format("{}h{:02}m", s / 3600, (s % 3600) / 60);
}

// "generation 2 (3/50)" ("batch 2 (3/300)" in MAP-Elites runs): the generation's number as stats.csv, the population
// files and the summary give it (from 0), then how many of how many are done.
std::string format_line(const ProgressLine& r) {
    const std::string of = r.max_generations > 0 ? fmt::format("/{}", r.max_generations) : "";
    if (r.coverage >= 0)
        return fmt::format("batch {} ({}{})  {:.1f} eval/s  best {:.6g}  mean {:.6g}  coverage {:.3f}  eta {}",
                           r.generation, r.generation + 1, of, r.evaluations_per_second, r.best, r.mean, r.coverage,
                           format_duration(r.eta_seconds));
    return fmt::format("generation {} ({}{})  {:.1f} eval/s  best {:.6g}  mean {:.6g}  limit {}  eta {}",
                       r.generation, r.generation + 1, of, r.evaluations_per_second, r.best, r.mean, r.limit,
                       format_duration(r.eta_seconds));
}

ProgressPrinter::ProgressPrinter(std::ostream& out, bool live, Verbosity verbosity)
    : out_(&out), live_(live), verbosity_(verbosity) {}

ProgressPrinter ProgressPrinter::for_stderr(Verbosity verbosity) {
    return ProgressPrinter(std::cerr, isatty(fileno(stderr)) != 0, verbosity);
}

ProgressPrinter::ProgressPrinter(ProgressPrinter&& other) noexcept
    : out_(other.out_), live_(other.live_), verbosity_(other.verbosity_), line_open_(other.line_open_),
      last_line_(std::move(other.last_line_)) {
    other.line_open_ = false;
}

ProgressPrinter::~ProgressPrinter() { finish(); }

void ProgressPrinter::operator()(const ProgressLine& record) {
    if (verbosity_ == Verbosity::Quiet) return;
    if (!live_ || verbosity_ == Verbosity::Verbose) {
        *out_ << format_line(record) << '\n' << std::flush;
        return;
    }
    // A bar of 20 cells when the total is known; \r + erase-line rewrites in place.
    std::string bar;
    if (record.max_generations > 0) {
        const int filled = std::clamp(record.generation * 20 / record.max_generations, 0, 20);
        bar = "[" + std::string(static_cast<std::size_t>(filled), '#') +
              std::string(static_cast<std::size_t>(20 - filled), '.') + "] ";
    }
    last_line_ = bar + format_line(record);
    *out_ << "\r\x1b[2K" << last_line_ << std::flush;
    line_open_ = true;
}

void ProgressPrinter::message(std::string_view text, bool detail) {
    if (verbosity_ == Verbosity::Quiet || (detail && verbosity_ != Verbosity::Verbose)) return;
    if (line_open_) {
        *out_ << "\r\x1b[2K" << text << '\n' << last_line_ << std::flush;
        return;
    }
    *out_ << text << '\n' << std::flush;
}

void ProgressPrinter::finish() {
    if (!line_open_) return;
    *out_ << '\n' << std::flush;
    line_open_ = false;
}

} // namespace cic::run
