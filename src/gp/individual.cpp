#include "cic/gp/individual.hpp"

#include <cmath>
#include <stdexcept>

namespace cic::gp {

bool better(const Individual& a, const Individual& b) {
    // A NaN fitness ranks below every number, so the order stays strict and total.
    const bool na = std::isnan(a.fitness), nb = std::isnan(b.fitness);
    if (na != nb) return nb;
    if (!na && a.fitness != b.fitness) return a.fitness > b.fitness;
    const std::size_t sa = a.size(), sb = b.size();
    if (sa != sb) return sa < sb;
    return a.id < b.id;
}

const Individual& Population::best() const {
    if (individuals.empty()) throw std::invalid_argument("Population::best: empty population");
    const Individual* b = nullptr;
    for (const auto& p : individuals) {
        if (!p) throw std::invalid_argument("Population::best: null individual");
        if (!b || better(*p, *b)) b = p.get();
    }
    return *b;
}

} // namespace cic::gp
