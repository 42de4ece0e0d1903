// libFuzzer target for the sweep-file reader:
//   the accepted plan or index must keep the reader's promises (fuzz_study_checks.hpp).
// The checks live in fuzz_study_checks.hpp (shared with tests/study/fuzz_study_regression_test.cpp).
// Run with scripts/fuzz.sh sweep SECONDS; see docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_study_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    return cic::fuzz::fuzz_verdict("fuzz_sweep", cic::fuzz::check_sweep(input));
}
