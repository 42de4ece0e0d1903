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

std::size_t GridSpec::cell_of(const std::vector<double>& descriptor) const {
    if (descriptor.size() != dimensions())
        throw std::invalid_argument("grid archive: a descriptor of " + std::to_string(descriptor.size()) +
                                    " values for a grid of " + std::to_string(dimensions()) + " dimensions");
    std::size_t cell = 0;
    for (std::size_t d = 0; d < descriptor.size(); ++d) {
        const double v = descriptor[d];
        if (!std::isfinite(v)) throw std::invalid_argument("grid archive: a descriptor value is not finite");
        // Clamped as a double: a value far outside the range must not
        // overflow the int (found by fuzzing the archive reader).
        const double t = std::floor((v - lo[d]) / (hi[d] - lo[d]) * bins[d]);
        const int bin = t < 0 ? 0 : t >= bins[d] ? bins[d] - 1 : static_cast<int>(t);
        cell = cell * static_cast<std::size_t>(bins[d]) + static_cast<std::size_t>(bin);
    }
    return cell;
}

std::vector<int> GridSpec::coordinates(std::size_t cell) const {
    if (cell >= cells()) throw std::invalid_argument("grid archive: no cell " + std::to_string(cell));
    std::vector<int> out(dimensions());
    for (std::size_t d = dimensions(); d-- > 0;) {
        out[d] = static_cast<int>(cell % static_cast<std::size_t>(bins[d]));
        cell /= static_cast<std::size_t>(bins[d]);
    }
    return out;
}

std::string GridSpec::cell_name(std::size_t cell) const {
    std::string out;
    for (int b : coordinates(cell)) out += (out.empty() ? "" : ",") + std::to_string(b);
    return out;
}

} // namespace cic::gp
