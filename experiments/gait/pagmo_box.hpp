#pragma once
// pagmo2 stepped one generation at a time, for cic's searches (search.cpp,
// cma_me_emitter.cpp). pagmo's algorithms evaluate inside evolve(); cic
// evaluates a generation as one batch, in worker processes. So a generation
// runs twice: first on copies, with a problem that only records the points it
// is asked for (the Ledger's first pass), then, once those are evaluated, for
// real, with the problem answering from the Ledger. pagmo is deterministic
// from its seed, so both passes ask for the same points.
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <pagmo/types.hpp>

#include "cic/core/rng.hpp"
#include "cic/experiments/gait/search.hpp"

namespace cic::gait::detail {

// Exact key of a point: its bits.
inline std::string key_of(const std::vector<double>& x) {
    std::string k(x.size() * sizeof(double), '\0');
    std::memcpy(k.data(), x.data(), k.size());
    return k;
}

// Shared by the problem copies pagmo makes: what this generation has evaluated,
// and in the first pass, what was asked for.
struct Ledger {
    bool recording = false;
    std::map<std::string, double> known;             // key -> cic fitness
    std::vector<std::vector<double>> asked;          // first pass, in order, without repeats
    const BatchEvaluator* late = nullptr;            // second pass: a point not foreseen
    long evaluated = 0;
};

struct BoxProblem {
    std::size_t n = 1;
    std::shared_ptr<Ledger> ledger = std::make_shared<Ledger>();

    pagmo::vector_double fitness(const pagmo::vector_double& x) const {
        const std::string k = key_of(x);
        if (auto it = ledger->known.find(k); it != ledger->known.end()) return {-it->second};
        if (ledger->recording) {
            ledger->known.emplace(k, 0.0);   // a placeholder, never read in the second pass
            ledger->asked.push_back(x);
            return {0.0};
        }
        if (!ledger->late) throw std::logic_error("gait search: a point was asked for outside a generation");
        const double f = (*ledger->late)({x}).at(0);
        ++ledger->evaluated;
        ledger->known.emplace(k, f);
        return {-f};
    }
    std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
        return {pagmo::vector_double(n, 0.0), pagmo::vector_double(n, 1.0)};
    }
    std::string get_name() const { return "cic gait (unit box)"; }
};

inline unsigned seed32(std::uint64_t seed, std::uint64_t salt) {
    Rng r(seed ^ (0x9e3779b97f4a7c15ULL * (salt + 1)));
    return static_cast<unsigned>(r.next() >> 32);
}

} // namespace cic::gait::detail
