#pragma once
// Population files: every individual with its trees as text, plus all the
// state a run needs to continue bit for bit (seed, RNG state, generation,
// bloat control, id counter). Human-readable and editable by hand.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <map>
#include <optional>

#include "cic/gp/evolution.hpp"
#include "cic/io/checkpoint_origin.hpp"
#include "cic/io/settings.hpp"

namespace cic::io {

struct PopulationFile {
    std::string experiment;               // "symreg" | "hypergp"
    std::string settings_digest;          // digest of the settings that shape the search
    int variables = 0;                    // genotype shape the file was made with
    std::vector<std::string> functions;
    int trees = 1;
    // Direct genes per individual beside the trees (Offset-HybrID's offsets,
    // gp::GpConfig::direct) and their range [-limit, limit]; 0 = none.
    std::size_t offsets = 0;
    double offset_limit = 0;
    gp::Population population;
    gp::EvolutionState state;
    // Switch-HybrID's stagnation clock (Neural.switchPatience), in the files of
    // its HyperGP phase: the best fitness so far and the first generation that
    // reached it. <switch bestFitness bestGeneration>; absent elsewhere.
    struct SwitchClock {
        double best = 0;
        int best_generation = 0;
    };
    std::optional<SwitchClock> switch_clock;
    // A growing robot's body this population is evaluated on (io/bodies.hpp):
    // <body index>, in the files of a growing run only.
    std::optional<std::size_t> body;
    // Where it came from (checkpoint_origin.hpp); none in files written before origins.
    std::optional<CheckpointOrigin> origin;
    std::map<std::uint64_t, int> lines;   // individual id -> line of its <individual> (files read)
};

// The shape fields, digest and origin of the given settings, with an empty population.
PopulationFile describe(const Settings& s);

std::string to_xml(const PopulationFile& p);
// Written atomically: nothing is ever half-written.
void save_population(const std::filesystem::path& path, const PopulationFile& p);
// Throws InputError "FILE:LINE: ..." for anything malformed, truncated or inconsistent.
PopulationFile load_population(const std::filesystem::path& path);
PopulationFile parse_population(std::string_view text, const std::string& name);

// Refuses a population made with another experiment type, variable count,
// function set or forest size, naming both values. `file` is for the message.
void check_compatible(const PopulationFile& loaded, const Settings& s, const std::string& file);

// A short hex digest of the settings that change what a run computes
// (everything but seed, output, workers, stop conditions and the load path;
// a value that computes as the default counts as the default). Legacy: the
// rule of files written before issue 55, which counted Simulator.collisionSpace
// 1 (sweep) apart from 0 (simple) though both give the same bits; a file's
// digest is the settings' own under either rule.
enum class DigestRule { Current, Legacy };
std::string settings_digest(const Settings& s, DigestRule rule = DigestRule::Current);

} // namespace cic::io
