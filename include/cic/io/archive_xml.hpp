#pragma once
// MAP-Elites archives as XML (population.xml and populations/gen-NNNN.xml of a
// run with MapElites.enabled; settings/cic-archive.xsd): the grid, each elite
// with its cell, fitness, descriptor and solution (a HyperGP genotype's trees
// or a gait's unit-box parameters), the counters and the random state, which
// with the settings are the whole state of the search: a resume continues bit
// for bit. Numbers are written with 17 significant digits (exact round trip).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cic/core/rng.hpp"
#include "cic/gp/grid_archive.hpp"
#include "cic/io/checkpoint_origin.hpp"
#include "cic/io/settings.hpp"
#include "cic/tree/tree.hpp"

namespace cic::io {

struct ArchiveElite {
    std::size_t cell = 0;
    double fitness = 0.0;
    std::vector<double> descriptor;
    std::vector<double> x;        // a gait run's parameters (empty for hypergp)
    tree::Forest genotype;        // a hypergp run's trees (empty for gait)
    int line = 0;                 // of its <elite> in the file read (0: made in memory)
};

// A digest of an elite (cell, fitness, descriptor, solution), written as
// <elite hash>: an edited fitness or solution is refused, as an archive's
// elites cannot be re-evaluated in place.
std::string elite_hash(const ArchiveElite& e);

struct ArchiveFile {
    std::string experiment;       // the experiment type's name
    std::string settings_digest;
    std::uint64_t seed = 0;
    int batches = 0;              // batches evaluated (the checkpoint's name is gen-(batches-1))
    long evaluations = 0;
    long failed = 0;
    Rng::State rng{};
    std::string descriptor;       // "duty-factor" | "omni"
    gp::GridSpec grid;
    std::vector<ArchiveElite> elites;   // in cell order
    int line = 0;                 // of <archive> in the file read (0: made in memory)
    // The emitter's own state, for an emitter that keeps one (CMA-ME), and
    // its MapElites.emitter name; both empty otherwise.
    std::string emitter;
    std::string emitter_state;
    // Where it came from (checkpoint_origin.hpp); none in files written before origins.
    std::optional<CheckpointOrigin> origin;

    const ArchiveElite* best() const;   // the fittest (the first in cell order among equals); nullptr when empty
    const ArchiveElite* at(std::size_t cell) const;
};

std::string to_xml(const ArchiveFile& a);
// Throws InputError "FILE:LINE: ..." for anything malformed, truncated or
// inconsistent (an elite outside its cell, counts that disagree).
ArchiveFile parse_archive(std::string_view text, const std::string& name);
ArchiveFile load_archive(const std::filesystem::path& path);

// Refuses an archive of another experiment, descriptor or grid than the
// settings make (grid = the one these settings and robot give), and one whose
// elites these settings cannot take: a gait elite of another length than
// `gait_dimension` (the parameters the settings make; 0 for a HyperGP run), a
// HyperGP elite of another tree count, or using a variable or function the
// settings do not have; or whose evaluations are not its batches times
// MapElites.batch. Each refusal names the file and the element's line.
void check_compatible(const ArchiveFile& a, const Settings& s, const gp::GridSpec& grid, std::size_t gait_dimension,
                      const std::string& file);

} // namespace cic::io
