#pragma once
// The names the Experiment.search key accepts: `auto` (the search the other
// keys imply: MapElites.enabled, Neural.switchPatience/switchShare, else the
// type's own) and every registered search (search/search.hpp registers them,
// built-in and out of tree alike). The io layer knows only the names and the
// genotype forms each works on; what a search does is the search layer's.
#include <string>
#include <string_view>
#include <vector>

#include "cic/io/experiment_types.hpp"
#include "cic/io/settings.hpp"

namespace cic::io {

struct SearchName {
    std::string name;                  // lower case, digits, '-' or '_'
    std::string doc;                   // one line, for `cic settings --defaults` and the man page
    std::vector<GenotypeForm> forms;   // the genotypes it varies
};

// The built-ins first (generational, evolution-strategy, map-elites,
// switch-hybrid: known here so that every reader and the schema know them),
// then registrations in their order.
const std::vector<SearchName>& search_names();
// nullptr for `auto` and for a name nothing registered.
const SearchName* find_search_name(std::string_view name);
// Adds a name; Experiment.search accepts it from then on. Throws
// std::invalid_argument for a bad or taken name, or one that varies nothing.
void register_search_name(SearchName name);
// One of the four built-ins (the search layer registers their behaviour, not their names).
bool is_builtin_search_name(std::string_view name);

// The name `auto` would pick for these settings (their Experiment.search read as
// `auto`), or "" when nothing varies their genotype or no search layer is linked.
// The search layer sets how it is found; the settings digest asks it so that
// naming the search `auto` picks anyway changes no digest (a resume from a
// checkpoint of the same run under `auto` is not "made with other settings").
using AutoSearchPick = std::string (*)(const Settings&);
void set_auto_search_pick(AutoSearchPick pick);
std::string auto_search_pick(const Settings& s);

} // namespace cic::io
