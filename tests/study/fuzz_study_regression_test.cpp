// The sweep and study-index fuzz targets' checks (fuzz/fuzz_study_checks.hpp)
// replayed in the normal test build, as tests/io/fuzz_regression_test.cpp does
// for the io readers: seeds are accepted, reproducers are handled cleanly, and
// the inputs of issue 24 are refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <map>

#include "fuzz_study_checks.hpp"   // fuzz/, shared with the fuzz targets
#include "support/fuzz_files.hpp"

namespace cic {
namespace {

namespace fs = std::filesystem;
using Check = std::function<fuzz::Outcome(std::string_view)>;

const std::map<std::string, Check>& checks() {
    static const std::map<std::string, Check> m = {{"sweep", fuzz::check_sweep}, {"index", fuzz::check_index}};
    return m;
}

std::vector<fs::path> files_of(const std::string& kind, const std::string& target) {
    return testing::fuzz_files(kind, target);
}
using testing::read_bytes;

TEST(FuzzStudyCorpora, SeedsAreAcceptedByTheirReader) {
    for (const auto& [target, check] : checks()) {
        const auto files = files_of("corpus", target);
        EXPECT_FALSE(files.empty()) << target;
        for (const auto& f : files) {
            const fuzz::Outcome o = check(read_bytes(f));
            EXPECT_EQ(o.verdict, fuzz::Verdict::Accepted) << f << ": " << o.problem;
        }
    }
}

TEST(FuzzStudyCorpora, EveryFileIsHandledCleanlyByBothReaders) {
    for (const char* kind : {"corpus", "regressions"})
        for (const auto& [target, unused] : checks())
            for (const auto& f : files_of(kind, target))
                for (const auto& [reader, check] : checks())
                    EXPECT_NE(check(read_bytes(f)).verdict, fuzz::Verdict::Bug) << f << " through " << reader;
}

// A seed set outside <repeats>, a study past a million runs, a non-finite
// metric: each was accepted before issue 24.
TEST(FuzzStudyRegressions, Issue24InputsAreRefused) {
    std::size_t seen = 0;
    for (const auto& [target, check] : checks())
        for (const auto& f : testing::issue24_inputs(target)) {
            ++seen;
            EXPECT_EQ(check(read_bytes(f)).verdict, fuzz::Verdict::Rejected) << f;
        }
    EXPECT_GE(seen, 5u);
}

} // namespace
} // namespace cic
