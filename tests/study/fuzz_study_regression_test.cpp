// The sweep and study-index fuzz targets' checks (fuzz/fuzz_study_checks.hpp)
// replayed in the normal test build, as tests/io/fuzz_regression_test.cpp does
// for the io readers: seeds are accepted, reproducers are handled cleanly, and
// the inputs of issue 24 are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "fuzz_study_checks.hpp"   // fuzz/, shared with the fuzz targets

namespace cic {
namespace {

namespace fs = std::filesystem;
const fs::path kFuzz = fs::path(CIC_SOURCE_DIR) / "fuzz";
using Check = std::function<fuzz::Outcome(std::string_view)>;

const std::map<std::string, Check>& checks() {
    static const std::map<std::string, Check> m = {{"sweep", fuzz::check_sweep}, {"index", fuzz::check_index}};
    return m;
}

std::string read_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::vector<fs::path> files_of(const std::string& kind, const std::string& target) {
    std::vector<fs::path> out;
    if (!fs::is_directory(kFuzz / kind / target)) return out;
    for (const auto& e : fs::directory_iterator(kFuzz / kind / target))
        if (e.is_regular_file()) out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

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
        for (const auto& f : files_of("regressions", target)) {
            if (f.filename().string().rfind("issue24-", 0) != 0) continue;
            ++seen;
            EXPECT_EQ(check(read_bytes(f)).verdict, fuzz::Verdict::Rejected) << f;
        }
    EXPECT_GE(seen, 5u);
}

} // namespace
} // namespace cic
