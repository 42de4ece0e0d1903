#pragma once
// The one random number generator of cic: xoshiro256** with our own
// distributions, so a seed gives the same numbers on every platform and
// standard library (std:: distributions are implementation-defined).
// Always passed explicitly; there is no global generator.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace cic {

class Rng {
public:
    using State = std::array<std::uint64_t, 4>;

    explicit Rng(std::uint64_t seed = 1);

    std::uint64_t next();
    double uniform();                        // [0, 1), 53 random bits
    double uniform(double lo, double hi);    // [lo, hi)
    std::uint64_t below(std::uint64_t n);    // [0, n), unbiased; n > 0
    std::size_t index(std::size_t n) { return static_cast<std::size_t>(below(n)); }
    int between(int lo, int hi);             // [lo, hi], inclusive
    bool bernoulli(double p);
    double normal();                         // standard normal (Box-Muller, no cached state)

    const State& state() const { return s_; }
    void set_state(const State& s);

    // "hex hex hex hex", for population files.
    std::string state_text() const;
    static State parse_state(const std::string& text); // throws std::invalid_argument

    // std::uniform_random_bit_generator, for std::shuffle-free helpers only.
    using result_type = std::uint64_t;
    static constexpr result_type min() { return 0; }
    static constexpr result_type max() { return ~result_type{0}; }
    result_type operator()() { return next(); }

private:
    State s_{};
};

// SplitMix64 finaliser: mixes a 64-bit value; used for seeding and hashing.
std::uint64_t mix64(std::uint64_t x);

} // namespace cic
