// libFuzzer target for the sweep-file reader:
//   the accepted plan or index must keep the reader's promises (fuzz_study_checks.hpp).
// The checks live in fuzz_study_checks.hpp (shared with tests/study/fuzz_study_regression_test.cpp).
// Run with scripts/fuzz.sh sweep SECONDS; see docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string_view>

#include "fuzz_study_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const cic::fuzz::Outcome o = cic::fuzz::check_sweep(std::string_view(reinterpret_cast<const char*>(data), size));
    if (o.verdict == cic::fuzz::Verdict::Bug) {
        std::fprintf(stderr, "fuzz_sweep: %s\n", o.problem.c_str());
        __builtin_trap();   // a broken promise: let libFuzzer keep the input as a crash
    }
    return 0;
}
