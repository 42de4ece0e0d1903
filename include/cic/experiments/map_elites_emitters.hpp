#pragma once
// The open registry of MAP-Elites emitters (MapElites.emitter; docs/extending.md,
// docs/quality-diversity.md). An emitter is how a run makes solutions from
// nothing and from the archive's elites (gp::Emitter). It varies one family's
// solutions: GP genotypes (hypergp family) or gait parameter vectors (gait
// family). A new emitter is one file with a static EmitterRegistrar: its name,
// one line of doc, and a factory for its family. The name joins the choices of
// MapElites.emitter (reader, schema, --help), and the settings check refuses
// it for the other family. The built-ins (gp, gaussian, iso-line, cma-me) are
// listed in map_elites_emitters.cpp.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "cic/gp/map_elites.hpp"
#include "cic/gp/vector_map_elites.hpp"
#include "cic/io/settings.hpp"
#include "cic/tree/primitives.hpp"
#include "cic/tree/tree.hpp"

namespace cic::experiments {

// A hypergp-family emitter from the run's settings (GP.* and MapElites.*) and
// primitive set (which outlives the emitter).
using ForestEmitterFactory =
    std::function<gp::Emitter<tree::Forest>(const io::Settings& s, const tree::PrimitiveSet& primitives)>;
// A gait-family emitter from the run's settings and the search's config (the
// grid, the vector's dimension, MapElites.sigma).
using VectorEmitterFactory =
    std::function<gp::Emitter<std::vector<double>>(const io::Settings& s, const gp::VectorMapElitesConfig& config)>;

struct EmitterKind {
    std::string name;   // the MapElites.emitter value
    std::string doc;    // one line
    // Exactly one of the two: it says the family.
    ForestEmitterFactory forest;
    VectorEmitterFactory vector;
    // Optional: throws cic::InputError naming the keys for settings this
    // emitter cannot run with (checked before a run writes anything).
    std::function<void(const io::Settings&)> check;
};

// Throws std::invalid_argument for a name registered twice or taken, or a kind
// with no factory or with both.
void register_emitter(EmitterKind kind);

// The emitter MapElites.emitter names (auto: gp, gaussian). Throws
// std::invalid_argument for a name nothing registered for this family, and
// whatever the factory throws.
gp::Emitter<tree::Forest> make_forest_emitter(const io::Settings& s, const tree::PrimitiveSet& primitives);
gp::Emitter<std::vector<double>> make_vector_emitter(const io::Settings& s, const gp::VectorMapElitesConfig& config);

// The named emitter's own check of the settings (MapElites enabled only).
void check_emitter(const io::Settings& s);

struct EmitterRegistrar {
    explicit EmitterRegistrar(EmitterKind kind) { register_emitter(std::move(kind)); }
};

} // namespace cic::experiments
