// Console progress: plain lines off a terminal, one live line on it, quiet and verbose.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "cic/run/progress.hpp"

namespace {

using namespace cic::run;

// Generation g (from 0) finished.
ProgressLine record(int g) { return {g - 1, 50, 123.4, 2.5 + g, 1.25, 17, 90.0}; }

int count(const std::string& s, const std::string& what) {
    int n = 0;
    for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
    return n;
}

TEST(Progress, FormatsDurations) {
    EXPECT_EQ(format_duration(0), "0s");
    EXPECT_EQ(format_duration(44.6), "45s");
    EXPECT_EQ(format_duration(187), "3m07s");
    EXPECT_EQ(format_duration(7500), "2h05m");
    EXPECT_EQ(format_duration(-1), "?");
    EXPECT_EQ(format_duration(std::nan("")), "?");
}

TEST(Progress, RecordLineHoldsEveryField) {
    const std::string line = format_line(record(12));
    EXPECT_EQ(line, "generation 11 (12/50)  123.4 eval/s  best 14.5  mean 1.25  limit 17  eta 1m30s");
    ProgressLine open = record(3);
    open.max_generations = 0;
    open.eta_seconds = -1;
    EXPECT_EQ(format_line(open).substr(0, 18), "generation 2 (3)  ");
    EXPECT_NE(format_line(open).find("eta ?"), std::string::npos);
    // A MAP-Elites run counts batches and shows the archive's coverage.
    ProgressLine batch = record(12);
    batch.coverage = 0.25;
    EXPECT_EQ(format_line(batch), "batch 11 (12/50)  123.4 eval/s  best 14.5  mean 1.25  coverage 0.250  eta 1m30s");
}

TEST(Progress, PlainLinesWhenNotATerminal) {
    std::ostringstream out;
    {
        ProgressPrinter p(out, false, Verbosity::Normal);
        p(record(1));
        p.message("checkpoint written");
        p.message("detail", true);
        p(record(2));
    }
    EXPECT_EQ(out.str(), format_line(record(1)) + "\ncheckpoint written\n" + format_line(record(2)) + "\n");
    EXPECT_EQ(out.str().find('\r'), std::string::npos);
}

TEST(Progress, OneLiveLineOnATerminal) {
    std::ostringstream out;
    ProgressPrinter p(out, true, Verbosity::Normal);
    p(record(1));
    p(record(2));
    EXPECT_EQ(count(out.str(), "\n"), 0);
    EXPECT_EQ(count(out.str(), "\r\x1b[2K"), 2);
    EXPECT_NE(out.str().find("[....................] generation 1 (2/50)"), std::string::npos);
    p.message("note");   // printed above the live line, which is redrawn
    EXPECT_NE(out.str().find("\r\x1b[2Knote\n[....................] generation 1 (2/50)"), std::string::npos);
    p.finish();
    EXPECT_EQ(out.str().back(), '\n');
    const auto size = out.str().size();
    p.finish();   // nothing more to end
    EXPECT_EQ(out.str().size(), size);
}

TEST(Progress, QuietPrintsNothingAndVerboseKeepsEveryLine) {
    std::ostringstream quiet, verbose;
    {
        ProgressPrinter q(quiet, true, Verbosity::Quiet);
        q(record(1));
        q.message("hello");
        ProgressPrinter v(verbose, true, Verbosity::Verbose);
        v(record(1));
        v(record(2));
        v.message("detail", true);
    }
    EXPECT_EQ(quiet.str(), "");
    EXPECT_EQ(verbose.str(), format_line(record(1)) + "\n" + format_line(record(2)) + "\ndetail\n");
}

} // namespace
