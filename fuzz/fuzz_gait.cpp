// libFuzzer target for the gait checkpoint reader:
//   cic::io::parse_gait, then to_xml / parse back.
// The checks live in fuzz_checks.hpp (shared with tests/io/fuzz_regression_test.cpp).
// Run with scripts/fuzz.sh gait SECONDS; see docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    return cic::fuzz::fuzz_verdict("fuzz_gait", cic::fuzz::check_gait(input));
}
