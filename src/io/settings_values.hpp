#pragma once
// Text <-> value conversions shared by the settings table and reader (private to src/io).
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "cic/io/settings_table.hpp"

namespace cic::io::detail {

// Shortest text that reads back to exactly v; "inf" / "-inf" for infinities.
std::string format_double(double v);
std::string join(const std::vector<std::string>& items, std::string_view sep = " ");
// Splits on whitespace; rejects commas with a hint (lists are space-separated).
std::vector<std::string_view> split_items(std::string_view text);

bool parse_bool(std::string_view text);
long long parse_integer(const SettingKey& k, std::string_view text);        // checks k's range
std::uint64_t parse_uint64(std::string_view text);
double parse_number(const SettingKey& k, std::string_view text);            // checks k's range
// Index of the choice whose spellings contain text; throws ValueError otherwise.
std::size_t parse_choice(const SettingKey& k, std::string_view text);

// The table and its sections, for the registrations that extend them
// (settings_extension.cpp, experiment_types.cpp); everything else reads them
// through settings_table() and settings_sections().
std::vector<SettingKey>& mutable_settings_table();
std::vector<std::string>& mutable_settings_sections();
// The sections of the plain config structs, in file order (no registered ones).
const std::vector<std::string>& builtin_settings_sections();
// The Experiment.type row: one of experiment_types() (experiment_types.cpp).
SettingKey experiment_type_row();
// The Neural.substrate row: one of substrate_names() (substrate_names.cpp).
SettingKey substrate_row();
// The MapElites.emitter row: auto or one of emitter_names() (emitter_names.cpp).
SettingKey emitter_row();
// Experiment.search (search_names.cpp).
SettingKey search_row();
// A name a registration may take: 1 to 40 of a-z, 0-9, '-' and '_', starting with a letter.
bool valid_registered_name(std::string_view name);
// A key whose value is one of a list that registrations extend (Experiment.type,
// Neural.substrate): `field` is the member it sets, `known` checks a name
// against the list when the value is read.
SettingKey open_choice_row(std::string section, std::string key, const std::vector<std::string>& names,
                           std::string doc, std::string& (*field)(Settings&), bool (*known)(std::string_view));
// Whether the table exists yet. A registration in a static initialiser must not
// build it: files whose statics the rows read may not be initialised yet.
bool settings_table_built();
// The table's row of section.key, given the list's names and doc again (after
// a registration); nothing when the table is not built yet (it will be built
// with the names as they are then).
void refresh_open_choice_row(std::string_view section, std::string_view key, const std::vector<std::string>& names,
                             const std::string& doc);

// Where each key got its value ("Section.key" -> file, line), so cross-field
// errors can point at the line the user wrote.
struct Location {
    std::string file;
    int line = 0;
};
using Locations = std::map<std::string, Location>;

// Cross-field checks; messages point at `locations` where known (settings_validate.cpp).
void validate(const Settings& s, const Locations& locations);

} // namespace cic::io::detail
