// The MAP-Elites emitter registry (map_elites_emitters.hpp) and its built-ins.
#include "cic/experiments/map_elites_emitters.hpp"

#include <stdexcept>
#include <string_view>

#include "cic/experiments/gait/cma_me_emitter.hpp"
#include "cic/gp/forest_map_elites.hpp"
#include "cic/io/emitter_names.hpp"
#include "cic/io/experiment_types.hpp"

namespace cic::experiments {
namespace {

// The built-ins' names and docs are io's (emitter_names.cpp), known there
// before any settings are read; here are their factories.
std::vector<EmitterKind>& kinds() {
    static std::vector<EmitterKind> k{
        {"gp", "", [](const io::Settings& s, const tree::PrimitiveSet& ps) { return gp::forest_emitter(s.gp, ps); },
         nullptr, nullptr},
        {"gaussian", "", nullptr,
         [](const io::Settings&, const gp::VectorMapElitesConfig& c) { return gp::gaussian_emitter(c); }, nullptr},
        {"iso-line", "", nullptr,
         [](const io::Settings& s, const gp::VectorMapElitesConfig& c) {
             return gp::iso_line_emitter(c, s.map_elites.line_sigma);
         },
         nullptr},
        {"cma-me", "", nullptr, &gait::cma_me_emitter, &gait::check_cma_me},
    };
    return k;
}

const EmitterKind& find(const io::Settings& s, io::ExperimentFamily family) {
    const std::string_view name = io::resolved_emitter(s);
    for (const auto& k : kinds())
        if (k.name == name && (family == io::ExperimentFamily::Gait ? bool(k.vector) : bool(k.forest))) return k;
    throw std::invalid_argument("map-elites: no " + std::string(io::to_string(family)) + "-family emitter named '" +
                                std::string(name) + "' is registered");
}

} // namespace

void register_emitter(EmitterKind kind) {
    if (bool(kind.forest) == bool(kind.vector))
        throw std::invalid_argument("emitter '" + kind.name + "': give exactly one factory, forest or vector");
    io::register_emitter_name({kind.name, kind.doc,
                               kind.forest ? io::ExperimentFamily::HyperGP : io::ExperimentFamily::Gait});
    kinds().push_back(std::move(kind));
}

void check_emitter(const io::Settings& s) {
    if (!s.map_elites.enabled) return;
    const io::ExperimentFamily family = io::family_of(s);
    if (family != io::ExperimentFamily::HyperGP && family != io::ExperimentFamily::Gait) return;
    if (const EmitterKind& k = find(s, family); k.check) k.check(s);
}

gp::Emitter<tree::Forest> make_forest_emitter(const io::Settings& s, const tree::PrimitiveSet& primitives) {
    return find(s, io::ExperimentFamily::HyperGP).forest(s, primitives);
}

gp::Emitter<std::vector<double>> make_vector_emitter(const io::Settings& s, const gp::VectorMapElitesConfig& config) {
    return find(s, io::ExperimentFamily::Gait).vector(s, config);
}

} // namespace cic::experiments
