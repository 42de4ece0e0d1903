#pragma once
// A MAP-Elites archive as a heatmap (`cic plot RUN --archive`, and `cic plot
// RUN` on an archive run): two descriptor dimensions inside each block, up to
// two more as a grid of blocks (2-D slices), each bin labelled with its
// number as `cic view --cell` takes it, the best cell framed; a fifth and
// further dimensions are collapsed to their best. Empty cells are white.
#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "cic/io/archive_xml.hpp"
#include "cic/report/plot.hpp"

namespace cic::report {

struct ArchiveMap {
    std::size_t x_dim = 0, y_dim = 0;   // the dimensions shown (0-based); y_dim == x_dim for a 1-D grid
    int x_bins = 1, y_bins = 1;
    double x_lo = 0, x_hi = 1, y_lo = 0, y_hi = 1;
    std::vector<double> best;           // y_bins rows of x_bins; NaN where no elite
};

// Throws cic::InputError for a dimension past the grid's, or two the same.
ArchiveMap collapse_archive(const io::ArchiveFile& archive, std::size_t x_dim, std::size_t y_dim);

// Where each cell goes on the heatmap: in bin units, the inner dimensions
// within a block, blocks one empty bin apart along the outer dimensions.
struct ArchiveSlices {
    std::size_t x_dim = 0, y_dim = 0;             // inner dimensions (y_dim == x_dim for a 1-D grid)
    std::vector<std::size_t> outer;               // 0, 1 or 2 dimensions: blocks along x, then along y
    int x_bins = 1, y_bins = 1, blocks_x = 1, blocks_y = 1;
    double width() const { return blocks_x * (x_bins + 1) - 1.0; }
    double height() const { return blocks_y * (y_bins + 1) - 1.0; }
    // The centre of the cell with these bins (one per grid dimension).
    std::array<double, 2> centre_of(const std::vector<int>& bins) const;
};
// Throws cic::InputError for a dimension past the grid's, or two the same.
ArchiveSlices slice_layout(const gp::GridSpec& grid, std::size_t x_dim, std::size_t y_dim);

// The heatmap's plot area as fractions of the image (left, right, bottom,
// top), fixed so that a cell's pixels can be found from its centre.
inline constexpr std::array<double, 4> kHeatmapArea = {0.10, 0.80, 0.14, 0.84};

// Whether a folder is a MAP-Elites run (its settings.xml enables MapElites).
bool is_archive_run(const std::filesystem::path& run_dir);

struct ArchivePlotOptions : PlotOptions {
    std::size_t x_dim = 0, y_dim = 1;   // 0-based; the CLI takes them from 1
};

// The heatmap of a MAP-Elites run folder's population.xml (or an archive file
// in a run folder), axes labelled with the descriptor (each foot's name for
// duty factors). Throws cic::InputError for a run that is not MAP-Elites.
void plot_archive(const std::filesystem::path& run_or_archive, const std::filesystem::path& out_file,
                  const ArchivePlotOptions& options = {});

} // namespace cic::report
