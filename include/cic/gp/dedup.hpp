#pragma once
// preventDuplicates: a set of genotypes keyed by structural hash and compared
// exactly, plus a bounded-retry helper for making a genotype not yet present.
#include <cstdint>
#include <functional>
#include <unordered_map>

#include "cic/tree/tree.hpp"

namespace cic::gp {

class GenotypeSet {
public:
    // True if f was not present (and is now). Equality is exact, so hash collisions are harmless.
    bool insert(const tree::Forest& f);
    bool contains(const tree::Forest& f) const;
    std::size_t size() const { return by_hash_.size(); }
    void clear() { by_hash_.clear(); }

private:
    std::unordered_multimap<std::uint64_t, tree::Forest> by_hash_;
};

// Calls make() until it yields a genotype not in `seen`, at most 1 + retries times
// (retries >= 0, else std::invalid_argument). Returns the last genotype made and
// inserts it; *unique (if given) says whether it was new. Deterministic when make() is.
tree::Forest make_unique(GenotypeSet& seen, int retries, const std::function<tree::Forest()>& make,
                         bool* unique = nullptr);

} // namespace cic::gp
