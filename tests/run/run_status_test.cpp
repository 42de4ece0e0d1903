// How a run ended, as its summary.txt says (run_status.hpp): the run loop's own
// line, and for summaries of cic before it, any "stopped: interrupted" line.
#include <gtest/gtest.h>

#include "cic/run/run_status.hpp"

namespace cic::run {
namespace {

TEST(RunStatus, TheLoopsLineRoundTrips) {
    for (RunEnd end : {RunEnd::Done, RunEnd::Interrupted})
        EXPECT_EQ(run_end_of_summary("stopped: whatever at generation 3\nbest: 1\n" + status_line(end) + "cic: x\n"), end);
    EXPECT_EQ(status_line(RunEnd::Interrupted), "status: interrupted\n");
}

TEST(RunStatus, TheLoopsLastLineCountsWhateverTheSearchWrote) {
    // A search's text cannot make an interrupted run read as done.
    EXPECT_EQ(run_end_of_summary("status: done\n" + status_line(RunEnd::Interrupted)), RunEnd::Interrupted);
    EXPECT_EQ(run_end_of_summary("stopped: interrupted at generation 2\n" + status_line(RunEnd::Done)), RunEnd::Done);
}

// Run folders written before the line: the stop line of any phase.
TEST(RunStatus, OlderSummariesAreReadByTheirStopLines) {
    EXPECT_EQ(run_end_of_summary("stopped: interrupted at generation 4\nbest: 2\ncic: 0.1.0\n"), RunEnd::Interrupted);
    EXPECT_EQ(run_end_of_summary("stopped: maximum iterations reached at generation 9\n"), RunEnd::Done);
    const std::string head = "HyperGP phase:\nstopped: handed over at generation 13\nbest: 9.6\n\ngait phase (sepcmaes):\n";
    EXPECT_EQ(run_end_of_summary(head + "stopped: interrupted at generation 30\n"), RunEnd::Interrupted);
    EXPECT_EQ(run_end_of_summary(head + "stopped: evaluation budget at generation 86\n"), RunEnd::Done);
    EXPECT_EQ(run_end_of_summary(head + "stopped: interrupted before the gait phase began\n"), RunEnd::Interrupted);
    EXPECT_EQ(run_end_of_summary(""), RunEnd::Done);
}

} // namespace
} // namespace cic::run
