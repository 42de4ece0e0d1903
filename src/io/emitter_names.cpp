// The names MapElites.emitter accepts (emitter_names.hpp) and its row.
#include "cic/io/emitter_names.hpp"

#include <stdexcept>

#include "cic/io/settings_table.hpp"
#include "settings_values.hpp"

namespace cic::io {
namespace {

constexpr std::size_t kBuiltins = 4;

std::vector<EmitterName>& names() {
    static std::vector<EmitterName> n{
        {"gp", "HyperGP's crossover and subtree mutation of elites", ExperimentFamily::HyperGP},
        {"gaussian", "isotropic Gaussian mutation of a gait vector", ExperimentFamily::Gait},
        {"iso-line", "Iso+LineDD: Gaussian plus a step along the line to a second elite", ExperimentFamily::Gait},
        {"cma-me", "CMA-ME's improvement emitter: a CMA-ES over the batch, from an elite", ExperimentFamily::Gait},
    };
    return n;
}

std::string emitter_doc() {
    std::string doc = "How elites are varied: auto (the family's own: gp for HyperGP genotypes, gaussian for gait "
                      "vectors), gp (crossover and subtree mutation; hypergp family), gaussian (isotropic Gaussian "
                      "mutation with MapElites.sigma; gait family), iso-line (Iso+LineDD, Vassiliades & Mouret "
                      "2018: MapElites.sigma isotropic plus MapElites.lineSigma along the line to a second elite; "
                      "gait family) or cma-me (CMA-ME's improvement emitter, Fontaine et al. 2020: a CMA-ES whose "
                      "population is the batch, started at an elite with step size MapElites.sigma, ranking its "
                      "offspring by what they add to the archive, restarted at another elite when a generation adds "
                      "nothing; gait family)";
    for (std::size_t i = kBuiltins; i < names().size(); ++i)
        doc += ". Registered: " + names()[i].name + " (" + std::string(to_string(names()[i].family)) + " family; " +
               names()[i].doc + ")";
    return doc;
}

std::vector<std::string> name_list() {
    std::vector<std::string> out{"auto"};
    for (const auto& n : names()) out.push_back(n.name);
    return out;
}

bool is_emitter_value(std::string_view name) { return name == "auto" || find_emitter_name(name) != nullptr; }

} // namespace

const std::vector<EmitterName>& emitter_names() { return names(); }

const EmitterName* find_emitter_name(std::string_view name) {
    for (const auto& n : names())
        if (n.name == name) return &n;
    return nullptr;
}

std::string_view default_emitter(ExperimentFamily family) {
    return family == ExperimentFamily::Gait ? "gaussian" : "gp";
}

std::string_view resolved_emitter(const Settings& s) {
    return s.map_elites.emitter == "auto" ? default_emitter(family_of(s)) : std::string_view(s.map_elites.emitter);
}

void register_emitter_name(EmitterName name) {
    if (!detail::valid_registered_name(name.name) || name.name == "auto")
        throw std::invalid_argument("emitter name '" + name.name +
                                    "': use 1 to 40 of a-z, 0-9, '-' and '_', starting with a letter, not 'auto'");
    if (name.family != ExperimentFamily::HyperGP && name.family != ExperimentFamily::Gait)
        throw std::invalid_argument("emitter '" + name.name + "': MAP-Elites varies hypergp or gait solutions only");
    if (find_emitter_name(name.name)) throw std::invalid_argument("emitter '" + name.name + "' is registered twice");
    names().push_back(std::move(name));
    detail::refresh_open_choice_row("MapElites", "emitter", name_list(), emitter_doc());
}

namespace detail {

SettingKey emitter_row() {
    SettingKey k = open_choice_row("MapElites", "emitter", name_list(), emitter_doc(),
                                   [](Settings& s) -> std::string& { return s.map_elites.emitter; }, &is_emitter_value);
    k.digest_at_default = false;   // added after the first MAP-Elites runs: out of the digest at its default
    return k;
}

} // namespace detail
} // namespace cic::io
