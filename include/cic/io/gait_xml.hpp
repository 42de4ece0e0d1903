#pragma once
// Checkpoints of the gait experiment (population.xml and populations/gen-NNNN.xml
// of a gait run): the optimiser's candidates, the best point found, counters,
// and the fitness history, which with the seed is the optimiser's whole state
// (experiments/gait/search.hpp): a resume re-runs the optimiser from them and
// continues bit for bit. Numbers are written with 17 significant digits (exact
// round trip).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cic/io/checkpoint_origin.hpp"
#include "cic/io/settings.hpp"

namespace cic::io {

struct GaitPoint {
    std::vector<double> x;    // unit-box parameters (experiments/gait/encoding.hpp)
    double fitness = 0.0;
};

// The IPOP restarts of a run (Gait.restarts = ipop), for a person to read and
// for a resume to check against the replay: <restarts count populationSize
// generations>.
struct GaitRestartRecord {
    int count = 0;                       // starts begun after the first
    int population_size = 0;             // the current start's lambda (= the candidates)
    std::vector<int> generations;        // the generation of each restart's first batch
};

// Switch-HybrID's gait phase (Neural.switchPatience / switchShare): where the
// HyperGP phase ended, and the start point of the search (Search::set_start).
struct GaitHandover {
    int generation = 0;                  // the last HyperGP generation
    long evaluations = 0;                // HyperGP's evaluations, before the gait's
    std::vector<double> x;               // the best individual's gait, centred layout
};

struct GaitFile {
    std::string settings_digest;
    std::string optimizer;               // cmaes | xnes | sade
    std::uint64_t seed = 0;
    int generation = 0;
    long evaluations = 0;
    std::size_t dimension = 0;
    std::vector<GaitPoint> population;
    GaitPoint champion;                  // the best point of the run so far
    std::vector<double> history;         // every fitness evaluated, in order
    // Written by runs with restarts only; files without it (restarts = none,
    // or made before the key) load as before.
    std::optional<GaitRestartRecord> restarts;
    std::optional<GaitHandover> handover;   // a Switch-HybrID run's gait phase only
    // Where it came from (checkpoint_origin.hpp); none in files written before origins.
    std::optional<CheckpointOrigin> origin;
};

// A digest of the state a resume believes (seed, counters, points, history,
// restarts), written as <gaitRun contentHash>: a hand edit is refused, since a
// gait checkpoint cannot be re-evaluated in part.
std::string content_hash(const GaitFile& g);

std::string to_xml(const GaitFile& g);
// Throws InputError "FILE:LINE: ..." for anything malformed, truncated or inconsistent.
GaitFile parse_gait(std::string_view text, const std::string& name);
GaitFile load_gait(const std::filesystem::path& path);
// Whether the file's root element is a gait checkpoint (cheap: reads the start).
bool is_gait_file(const std::filesystem::path& path);

// Refuses a checkpoint of another optimiser or parameter count than the
// settings give (dimension = the parameters these settings make).
void check_compatible(const GaitFile& g, const Settings& s, std::size_t dimension, const std::string& file);

} // namespace cic::io
