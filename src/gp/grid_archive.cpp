#include "cic/gp/grid_archive.hpp"

namespace cic::gp {

void GridSpec::validate() const {
    if (bins.empty()) throw std::invalid_argument("grid archive: no dimension");
    if (lo.size() != bins.size() || hi.size() != bins.size())
        throw std::invalid_argument("grid archive: " + std::to_string(bins.size()) + " bin counts but " +
                                    std::to_string(lo.size()) + " lower and " + std::to_string(hi.size()) +
                                    " upper bounds");
    for (std::size_t d = 0; d < bins.size(); ++d) {
        if (bins[d] < 1) throw std::invalid_argument("grid archive: dimension " + std::to_string(d) + " has no bin");
        if (!std::isfinite(lo[d]) || !std::isfinite(hi[d]) || !(lo[d] < hi[d]))
            throw std::invalid_argument("grid archive: dimension " + std::to_string(d) +
                                        " needs finite bounds with lo < hi");
    }
    cells();   // throws past the limit
}

std::size_t GridSpec::cells() const {
    std::size_t n = 1;
    for (int b : bins) {
        if (b < 1 || n > kMaxCells / static_cast<std::size_t>(b))
            throw std::invalid_argument("grid archive: more than " + std::to_string(kMaxCells) + " cells");
        n *= static_cast<std::size_t>(b);
    }
    return n;
}

} // namespace cic::gp
