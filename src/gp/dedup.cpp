#include "cic/gp/dedup.hpp"

#include <stdexcept>
#include <string>

namespace cic::gp {

bool GenotypeSet::contains(const tree::Forest& f) const {
    const auto [b, e] = by_hash_.equal_range(tree::hash(f));
    for (auto it = b; it != e; ++it)
        if (it->second == f) return true;
    return false;
}

bool GenotypeSet::insert(const tree::Forest& f) {
    if (contains(f)) return false;
    by_hash_.emplace(tree::hash(f), f);
    return true;
}

tree::Forest make_unique(GenotypeSet& seen, int retries, const std::function<tree::Forest()>& make, bool* unique) {
    if (retries < 0) throw std::invalid_argument("make_unique: retries must be >= 0, got " + std::to_string(retries));
    if (!make) throw std::invalid_argument("make_unique: no generator given");
    for (int attempt = 0;; ++attempt) {
        tree::Forest f = make();
        const bool fresh = seen.insert(f);
        if (fresh || attempt >= retries) {
            if (unique) *unique = fresh;
            return f;
        }
    }
}

} // namespace cic::gp
