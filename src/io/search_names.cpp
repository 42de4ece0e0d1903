// The names Experiment.search accepts (search_names.hpp) and its row.
#include "cic/io/search_names.hpp"

#include <stdexcept>

#include "cic/io/settings_table.hpp"
#include "settings_values.hpp"

namespace cic::io {
namespace {

constexpr std::size_t kBuiltins = 4;

// The built-ins are known here, as the built-in types and emitters are, so that
// every reader and the schema know them without the search layer linked; the
// search layer registers what they do (search/*.cpp).
std::vector<SearchName>& names() {
    static std::vector<SearchName> n{
        {"generational", "the thesis's generational GP (fig. 5.2): GP.* and Bloat.* keys, Control.maximumIterations "
                         "generations", {GenotypeForm::Trees}},
        {"evolution-strategy", "an evolution strategy on the gait vector: Gait.optimizer (cmaes, xnes, sade, "
                               "sepcmaes) with Gait.restarts, Gait.evaluations evaluations", {GenotypeForm::Vector}},
        {"map-elites", "MAP-Elites over a grid of behaviours (MapElites.* keys), MapElites.evaluations evaluations",
         {GenotypeForm::Trees, GenotypeForm::Vector}},
        {"switch-hybrid", "Switch-HybrID: generational HyperGP-gait, then the evolution strategy on the best's gait "
                          "(Neural.switchPatience, switchShare), Gait.evaluations over both phases",
         {GenotypeForm::Trees}},
    };
    return n;
}

std::string search_doc() {
    std::string doc = "The search that drives the run (docs/extending.md, \"A new search\"): auto (the one the other "
                      "keys imply: map-elites with MapElites.enabled = 1, switch-hybrid with Neural.switchPatience or "
                      "switchShare, else generational GP for trees and the evolution strategy Gait.optimizer names for "
                      "gait vectors)";
    for (const auto& n : names()) {
        std::string forms;
        for (const auto f : n.forms) forms += (forms.empty() ? "" : ", ") + std::string(to_string(f));
        doc += "; " + n.name + " (" + forms + "): " + n.doc;
    }
    return doc;
}

std::vector<std::string> name_list() {
    std::vector<std::string> out{"auto"};
    for (const auto& n : names()) out.push_back(n.name);
    return out;
}

bool is_search_value(std::string_view name) { return name == "auto" || find_search_name(name) != nullptr; }

} // namespace

const std::vector<SearchName>& search_names() { return names(); }

const SearchName* find_search_name(std::string_view name) {
    for (const auto& n : names())
        if (n.name == name) return &n;
    return nullptr;
}

bool is_builtin_search_name(std::string_view name) {
    for (std::size_t i = 0; i < kBuiltins; ++i)
        if (names()[i].name == name) return true;
    return false;
}

void register_search_name(SearchName name) {
    if (!detail::valid_registered_name(name.name) || name.name == "auto")
        throw std::invalid_argument("search name '" + name.name +
                                    "': use 1 to 40 of a-z, 0-9, '-' and '_', starting with a letter, not 'auto'");
    if (name.forms.empty()) throw std::invalid_argument("search '" + name.name + "' names no genotype form it varies");
    if (find_search_name(name.name)) throw std::invalid_argument("search '" + name.name + "' is registered twice");
    names().push_back(std::move(name));
    detail::refresh_open_choice_row("Experiment", "search", name_list(), search_doc());
}

namespace {
AutoSearchPick& pick_function() {
    static AutoSearchPick pick = nullptr;
    return pick;
}
} // namespace

void set_auto_search_pick(AutoSearchPick pick) { pick_function() = pick; }

std::string auto_search_pick(const Settings& s) {
    if (!pick_function()) return {};
    Settings as_auto = s;
    as_auto.experiment.search = "auto";
    return pick_function()(as_auto);
}

namespace detail {

SettingKey search_row() {
    SettingKey k = open_choice_row("Experiment", "search", name_list(), search_doc(),
                                   [](Settings& s) -> std::string& { return s.experiment.search; }, &is_search_value);
    k.digest_at_default = false;   // added after the first runs: `auto` keeps every digest as it was
    return k;
}

} // namespace detail
} // namespace cic::io
