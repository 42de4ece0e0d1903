#pragma once
// A MAP-Elites grid archive (Mouret & Clune 2015, "Illuminating search spaces
// by mapping elites"; the duty-factor grid of Cully et al. 2015): the behaviour
// space is cut into a grid of cells, each cell keeps the best solution found
// with a behaviour in it. Generic over the solution (a HyperGP genotype, a gait
// parameter vector). Deterministic: cells are kept in index order, a tie keeps
// the incumbent, and elites are drawn with the caller's Rng.
//
// The quality-diversity measures are those of QDax and pyribs: coverage (the
// share of cells filled), QD-score (the sum over filled cells of fitness minus
// an offset that makes every fitness positive) and the best fitness.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <iterator>
#include <utility>
#include <vector>

#include "cic/core/rng.hpp"

namespace cic::gp {

// The grid: per descriptor dimension, its number of bins and its range. A
// value below `lo` counts in the first bin, one at or above `hi` in the last.
struct GridSpec {
    std::vector<int> bins;
    std::vector<double> lo, hi;

    std::size_t dimensions() const { return bins.size(); }
    // Throws std::invalid_argument: no dimension, sizes that differ, a bin count
    // below 1, a range that is empty or not finite, more than kMaxCells cells.
    void validate() const;
    std::size_t cells() const;

    // The cell of a descriptor: row-major over the dimensions (the last
    // fastest). Throws std::invalid_argument for a descriptor of another size
    // or a value that is not finite.
    std::size_t cell_of(const std::vector<double>& descriptor) const;
    // The bin of each dimension of a cell; throws for a cell past the grid.
    std::vector<int> coordinates(std::size_t cell) const;
    // "I,J,...": the cell's bins, as `--cell` takes them and `cic export` writes them.
    std::string cell_name(std::size_t cell) const;

    static constexpr std::size_t kMaxCells = 10'000'000;
};

template <class Solution>
class GridArchive {
public:
    struct Elite {
        std::vector<double> descriptor;   // as measured, not the cell's centre
        double fitness = 0;
        Solution solution;
    };

    explicit GridArchive(GridSpec spec) : spec_(std::move(spec)) {
        spec_.validate();
        cells_ = spec_.cells();
    }

    const GridSpec& spec() const { return spec_; }
    std::size_t cells() const { return cells_; }

    std::size_t cell_of(const std::vector<double>& descriptor) const { return spec_.cell_of(descriptor); }
    std::vector<int> coordinates(std::size_t cell) const { return spec_.coordinates(cell); }

    // Keeps the solution when its cell is empty or it is strictly fitter than
    // the cell's elite (a tie keeps the incumbent). Returns whether it was kept.
    bool offer(std::vector<double> descriptor, double fitness, Solution solution) {
        if (!std::isfinite(fitness)) throw std::invalid_argument("grid archive: fitness is not finite");
        const std::size_t cell = cell_of(descriptor);
        auto it = elites_.find(cell);
        if (it != elites_.end() && !(fitness > it->second.fitness)) return false;
        elites_[cell] = Elite{std::move(descriptor), fitness, std::move(solution)};
        return true;
    }

    // Puts an elite back as saved (a checkpoint), refusing one in the wrong cell.
    void restore(std::size_t cell, Elite elite) {
        if (cell_of(elite.descriptor) != cell)
            throw std::invalid_argument("grid archive: an elite saved in cell " + std::to_string(cell) +
                                        " has a descriptor of cell " + std::to_string(cell_of(elite.descriptor)));
        if (!std::isfinite(elite.fitness)) throw std::invalid_argument("grid archive: fitness is not finite");
        if (!elites_.emplace(cell, std::move(elite)).second)
            throw std::invalid_argument("grid archive: cell " + std::to_string(cell) + " restored twice");
    }

    const std::map<std::size_t, Elite>& elites() const { return elites_; }
    const Elite* at(std::size_t cell) const {
        const auto it = elites_.find(cell);
        return it == elites_.end() ? nullptr : &it->second;
    }
    std::size_t filled() const { return elites_.size(); }
    bool empty() const { return elites_.empty(); }
    double coverage() const { return static_cast<double>(elites_.size()) / static_cast<double>(cells_); }

    // Sum over filled cells of (fitness - offset); choose offset below every
    // fitness a run can reach, and report it with the score.
    double qd_score(double offset) const {
        double sum = 0;
        for (const auto& [cell, e] : elites_) sum += e.fitness - offset;
        return sum;
    }

    // The fittest elite (the first in cell order among equals); nullptr when empty.
    const Elite* best() const {
        const Elite* out = nullptr;
        for (const auto& [cell, e] : elites_)
            if (!out || e.fitness > out->fitness) out = &e;
        return out;
    }

    // A filled cell drawn uniformly (MAP-Elites' parent selection).
    std::size_t random_cell(Rng& rng) const {
        if (elites_.empty()) throw std::logic_error("grid archive: no elite to draw from an empty archive");
        auto it = elites_.begin();
        std::advance(it, static_cast<long>(rng.index(elites_.size())));
        return it->first;
    }

private:
    GridSpec spec_;
    std::size_t cells_ = 0;
    std::map<std::size_t, Elite> elites_;
};

} // namespace cic::gp
