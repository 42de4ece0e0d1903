// The digest of the settings that change what a run computes. Stored in every
// population file so a resume with other settings is noticed.
#include <set>
#include "cic/io/experiment_types.hpp"
#include <string>

#include "cic/core/hash.hpp"
#include "cic/core/rng.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/search_names.hpp"
#include "cic/io/settings_table.hpp"
#include "cic/sim/config.hpp"

namespace cic::io {

std::string settings_digest(const Settings& s, DigestRule rule) {
    // Keys that never change the individuals a generation produces.
    static const std::set<std::string> ignored = {
        "Experiment.seed", "Experiment.outputDirectory", "Experiment.workers", "Experiment.checkpointInterval",
        "Experiment.workerTimeout", "Experiment.name", "Simulator.generatePovrayFiles"};
    std::string lines;
    for (const auto& k : settings_table()) {
        const std::string full = k.section + "." + k.key;
        if (k.section == "Control" || ignored.count(full)) continue;
        // The gait baseline's keys shape only gait runs.
        if (k.section == "Gait" && family_of(s) != ExperimentFamily::Gait) continue;
        // The restart keys shape only runs with restarts (so other gait runs keep the digest they had before them).
        if (k.section == "Gait" && k.key.rfind("restart", 0) == 0 && s.gait.restarts == GaitRestarts::None) continue;
        // MAP-Elites keys shape only MAP-Elites runs (so every other run keeps its digest).
        if (k.section == "MapElites" && !s.map_elites.enabled) continue;
        const std::string value = k.get(s);
        if (rule == DigestRule::Current) {
            if (!k.digest_at_default && value == default_text(k)) continue;
            if (value != default_text(k) && computes_as_default(k, value)) continue;   // the same bits by another route
        } else if (full == "Simulator.collisionSpace") {
            if (value == std::to_string(sim::kCollisionSimple)) continue;   // its default until issue 55
        } else if (!k.digest_at_default && value == default_text(k)) {
            continue;
        }
        // A search named explicitly that `auto` picks anyway computes the same run.
        if (full == "Experiment.search" && value == auto_search_pick(s)) continue;
        lines += full + "=" + value + "\n";
    }
    return hex16(mix64(fnv1a_64(lines)));
}

} // namespace cic::io
