#pragma once
// Reading, overriding, validating and writing settings files. Every function
// is driven by the table in settings_table.hpp. All errors on user input are
// cic::InputError with one line naming file:line, section, key, the value given
// and what is allowed.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "cic/core/error.hpp"
#include "cic/io/settings.hpp"

namespace cic::io {

namespace xml {
struct Format;
}
// Settings files as the strict reader knows them (io/strict_xml.hpp): the
// schema generated from the table, and messages that name the right section.
const xml::Format& settings_format();

// Reads a settings file onto the defaults and validates it (cross-field checks
// included). Relative paths inside the file are resolved against its folder.
Settings read_settings(const std::filesystem::path& file);

// Same for XML text; `name` stands for the file in messages.
Settings read_settings_string(std::string_view xml, const std::string& name = "<string>");

// Applies the file (empty path = defaults only), then the overrides
// ("Section.key=value", named "--set" in messages; a later one wins), then
// validates. This is what `cic` runs.
Settings load_settings(const std::filesystem::path& file, const std::vector<std::string>& overrides);

// The same on the text of `file` as it was read earlier (a sweep reads its base
// once, so that an edit while its runs go on changes none of them); `file`
// names it in messages and anchors its relative paths.
Settings load_settings_text(std::string_view text, const std::filesystem::path& file,
                            const std::vector<std::string>& overrides);

// An InputError "<Section> key = "value": MESSAGE" at the file and line where
// the first of `keys` the user wrote was set (else at the settings file), for
// a check of the settings made after they were read (a budget, a grid).
InputError key_error(const Settings& s, const std::vector<std::string>& keys, const std::string& message);

// Cross-field checks (min depth <= max depth, rates sum <= 1, ...). Throws InputError.
void validate_settings(const Settings& s);

// The effective settings as XML: every key, defaults filled in. With
// `documented`, each key is preceded by a comment with its doc, allowed values
// and default. Reads back to the same Settings.
std::string write_settings(const Settings& s, bool documented = false);

// The XSD schema generated from the table (committed as settings/cic-settings.xsd).
std::string settings_schema();

// A compact listing of every section and key, for --help.
std::string settings_key_listing();

} // namespace cic::io
