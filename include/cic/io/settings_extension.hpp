#pragma once
// Settings keys that an experiment type registered from outside brings, in a
// section of its own (docs/extending.md). They join the one settings table, so
// the reader, the writer, the schema, --help, `cic settings --defaults` and
// the settings digest treat them as every other key; their values live in
// Settings::extra as canonical text, read back typed with extra_*().
#include <string>
#include <string_view>
#include <vector>

#include "cic/io/settings_table.hpp"

namespace cic::io {

// A number in [min, max] (inclusive).
SettingKey extra_number_key(std::string section, std::string key, double default_value, double min, double max,
                            std::string doc);
// An integer in [min, max].
SettingKey extra_integer_key(std::string section, std::string key, long long default_value, long long min,
                             long long max, std::string doc);
// One of `choices` (the first spelling of each is the canonical one).
SettingKey extra_choice_key(std::string section, std::string key, std::vector<std::string> choices,
                            std::string default_value, std::string doc);

// Adds keys to the settings table; a section not yet known is appended to the
// sections. Register before reading settings. Throws std::invalid_argument for
// a key that exists, a key of a built-in section, or a key not made by extra_*_key.
void register_settings_keys(std::vector<SettingKey> keys);

// The value of a registered key in s (its default when the file did not set it).
// Throws std::invalid_argument when no such key is registered.
double extra_number(const Settings& s, std::string_view section, std::string_view key);
long long extra_integer(const Settings& s, std::string_view section, std::string_view key);
std::string extra_choice(const Settings& s, std::string_view section, std::string_view key);

} // namespace cic::io
