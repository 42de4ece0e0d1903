#pragma once
// The names the MapElites.emitter key accepts: `auto` (the family's own), the
// four built-in emitters (gp, gaussian, iso-line, cma-me) and those an emitter
// registration adds (experiments::register_emitter, docs/extending.md). Each
// name varies one family's solutions: GP genotypes or gait parameter vectors.
#include <string>
#include <string_view>
#include <vector>

#include "cic/io/experiment_types.hpp"
#include "cic/io/settings.hpp"

namespace cic::io {

struct EmitterName {
    std::string name;                                   // lower case, digits, '-' or '_'
    std::string doc;                                    // one line
    ExperimentFamily family = ExperimentFamily::HyperGP;   // whose solutions it varies: HyperGP or Gait
};

// Built-ins first (without `auto`), then registrations in their order.
const std::vector<EmitterName>& emitter_names();
// nullptr for `auto` and for a name nothing registered.
const EmitterName* find_emitter_name(std::string_view name);
// The emitter `auto` stands for in a family: gp (HyperGP) or gaussian (Gait).
std::string_view default_emitter(ExperimentFamily family);
// The emitter the settings vary elites with: MapElites.emitter, `auto` resolved.
std::string_view resolved_emitter(const Settings& s);
// Adds a name; the MapElites.emitter key accepts it from then on. Register
// before reading settings. Throws std::invalid_argument for a bad or taken
// name, or a family other than HyperGP and Gait.
void register_emitter_name(EmitterName name);

} // namespace cic::io
