#pragma once
// A MAP-Elites archive as a heatmap (`cic plot RUN --archive`): two descriptor
// dimensions on the axes, each shown cell coloured by the best fitness over
// the dimensions not shown (they are collapsed to their best), empty cells
// left white.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "cic/io/archive_xml.hpp"
#include "cic/report/plot.hpp"

namespace cic::app {

struct ArchiveMap {
    std::size_t x_dim = 0, y_dim = 0;   // the dimensions shown (0-based); y_dim == x_dim for a 1-D grid
    int x_bins = 1, y_bins = 1;
    double x_lo = 0, x_hi = 1, y_lo = 0, y_hi = 1;
    std::vector<double> best;           // y_bins rows of x_bins; NaN where no elite
};

// Throws cic::InputError for a dimension past the grid's, or two the same.
ArchiveMap collapse_archive(const io::ArchiveFile& archive, std::size_t x_dim, std::size_t y_dim);

struct ArchivePlotOptions : PlotOptions {
    std::size_t x_dim = 0, y_dim = 1;   // 0-based; the CLI takes them from 1
};

// The heatmap of a MAP-Elites run folder's population.xml (or an archive file
// in a run folder), axes labelled with the descriptor (each foot's name for
// duty factors). Throws cic::InputError for a run that is not MAP-Elites.
void plot_archive(const std::filesystem::path& run_or_archive, const std::filesystem::path& out_file,
                  const ArchivePlotOptions& options = {});

} // namespace cic::app
