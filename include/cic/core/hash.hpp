#pragma once
// 64-bit FNV-1a: a fixed, platform-independent hash of bytes, for names and
// fingerprints that must be the same on every machine (benchmark seeds, run
// store keys, the tests' golden hashes). Not for security.
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace cic {

constexpr std::uint64_t fnv1a_64(std::string_view bytes) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (char c : bytes) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
    return h;
}

// As 16 lower-case hex digits.
inline std::string hex16(std::uint64_t h) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

} // namespace cic
