#include "cic/core/rng.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace cic {

std::uint64_t mix64(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

Rng::Rng(std::uint64_t seed) {
    std::uint64_t z = seed;
    for (auto& w : s_) {
        z = mix64(z);
        w = z;
    }
    if ((s_[0] | s_[1] | s_[2] | s_[3]) == 0) s_[0] = 1; // all-zero state is a fixed point
}

// Lemire's method needs a 128-bit product; __extension__ keeps -Wpedantic quiet.
__extension__ typedef unsigned __int128 u128;

static inline std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

std::uint64_t Rng::next() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
}

double Rng::uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

double Rng::uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

std::uint64_t Rng::below(std::uint64_t n) {
    if (n == 0) throw std::invalid_argument("Rng::below: n must be positive");
    // Lemire's nearly-divisionless method.
    u128 m = static_cast<u128>(next()) * n;
    auto low = static_cast<std::uint64_t>(m);
    if (low < n) {
        const std::uint64_t threshold = (0 - n) % n;
        while (low < threshold) {
            m = static_cast<u128>(next()) * n;
            low = static_cast<std::uint64_t>(m);
        }
    }
    return static_cast<std::uint64_t>(m >> 64);
}

int Rng::between(int lo, int hi) {
    if (hi < lo) throw std::invalid_argument("Rng::between: hi < lo");
    return lo + static_cast<int>(below(static_cast<std::uint64_t>(hi - lo) + 1));
}

bool Rng::bernoulli(double p) { return uniform() < p; }

double Rng::normal() {
    double u1 = uniform();
    while (u1 <= 0.0) u1 = uniform();
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

void Rng::set_state(const State& s) {
    if ((s[0] | s[1] | s[2] | s[3]) == 0) throw std::invalid_argument("Rng state must not be all zero");
    s_ = s;
}

std::string Rng::state_text() const {
    char buf[4 * 17 + 1];
    std::snprintf(buf, sizeof buf, "%016llx %016llx %016llx %016llx",
                  static_cast<unsigned long long>(s_[0]), static_cast<unsigned long long>(s_[1]),
                  static_cast<unsigned long long>(s_[2]), static_cast<unsigned long long>(s_[3]));
    return buf;
}

Rng::State Rng::parse_state(const std::string& text) {
    std::istringstream in(text);
    State s{};
    for (auto& w : s) {
        std::string tok;
        if (!(in >> tok) || tok.size() > 16 || tok.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
            throw std::invalid_argument("RNG state must be four 64-bit hex words, got '" + text + "'");
        w = std::stoull(tok, nullptr, 16);
    }
    std::string extra;
    if (in >> extra) throw std::invalid_argument("RNG state has more than four words: '" + text + "'");
    if ((s[0] | s[1] | s[2] | s[3]) == 0) throw std::invalid_argument("RNG state must not be all zero");
    return s;
}

} // namespace cic
