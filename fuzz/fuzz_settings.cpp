// libFuzzer target for the settings reader:
//   cic::io::read_settings_string (which also validates), then write_settings / read back.
// The checks live in fuzz_checks.hpp (shared with tests/io/fuzz_regression_test.cpp).
// Run with scripts/fuzz.sh settings SECONDS; see docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string_view>

#include "fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const cic::fuzz::Outcome o = cic::fuzz::check_settings(std::string_view(reinterpret_cast<const char*>(data), size));
    if (o.verdict == cic::fuzz::Verdict::Bug) {
        std::fprintf(stderr, "fuzz_settings: %s\n", o.problem.c_str());
        __builtin_trap();   // a round-trip mismatch: let libFuzzer keep the input as a crash
    }
    return 0;
}
