// The digest of the settings that change what a run computes. Stored in every
// population file so a resume with other settings is noticed.
#include <cstdio>
#include <set>

#include "cic/core/rng.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings_table.hpp"

namespace cic::io {

std::string settings_digest(const Settings& s) {
    // Keys that never change the individuals a generation produces.
    static const std::set<std::string> ignored = {
        "Experiment.seed", "Experiment.outputDirectory", "Experiment.workers", "Experiment.checkpointInterval",
        "Experiment.workerTimeout", "Experiment.name", "Simulator.generatePovrayFiles"};
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const auto& k : settings_table()) {
        const std::string full = k.section + "." + k.key;
        if (k.section == "Control" || ignored.count(full)) continue;
        const std::string line = full + "=" + k.get(s) + "\n";
        for (unsigned char c : line) h = (h ^ c) * 0x100000001b3ULL;
    }
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(mix64(h)));
    return buf;
}

} // namespace cic::io
