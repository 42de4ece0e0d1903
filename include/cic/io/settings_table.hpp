#pragma once
// The one table of settings keys. Reader, writer, XSD schema, the documented
// defaults file and --help are all generated from it. A key's default is
// whatever the plain config structs hold by default (read through `get`).
// Adding a key = adding one row in settings_table.cpp.
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "cic/io/did_you_mean.hpp"   // edit_distance, for the nearest key
#include "cic/io/settings.hpp"

namespace cic::io {

enum class ValueType {
    Bool,        // 0 | 1 (true | false also read)
    Int,         // within [min, max]
    UInt64,      // 0 .. 2^64-1
    Double,      // within [min, max]; "inf" only when allow_inf
    String,      // free text; empty only when min_items == 0
    Path,        // a file path; relative paths in a file are resolved against its folder
    Enum,        // one of `choices`
    NameList,    // space-separated names from `choices`, no duplicates
    DoubleList,  // space-separated numbers, each within [min, max]
    IntList,     // space-separated integers, each within [min, max]
    PathList,    // space-separated file paths (none with spaces), each resolved as a Path
};

// Whether a value of this type is a space-separated list of items.
constexpr bool is_list(ValueType t) {
    return t == ValueType::NameList || t == ValueType::DoubleList || t == ValueType::IntList ||
           t == ValueType::PathList;
}

std::string_view type_name(ValueType t);

// A value the key cannot take; `what()` says why (without file or key,
// which the reader adds).
struct ValueError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct SettingKey {
    std::string section;            // "GP", "Simulator", ...
    std::string key;                // the thesis name where one exists
    ValueType type;
    std::string doc;                // one line
    double min = -std::numeric_limits<double>::max();   // numbers and list items (inclusive
    double max = std::numeric_limits<double>::max();    // unless min_exclusive)
    bool min_exclusive = false;
    bool allow_inf = false;         // Double: "inf" / "-inf" accepted
    std::size_t min_items = 1;      // lists: fewest items; String/Path: 0 = may be empty
    std::size_t max_items = std::numeric_limits<std::size_t>::max();
    // Enum / NameList: each choice is {written spelling, accepted aliases...}.
    std::vector<std::vector<std::string>> choices;
    std::function<std::string(const Settings&)> get;          // canonical text (writer)
    std::function<void(Settings&, std::string_view)> set;     // parse + assign; throws ValueError
    // false: the settings digest leaves the key out while it is at its default,
    // so that a key added after runs were made (its default keeping the old
    // behaviour) does not change the digest those runs' files hold.
    bool digest_at_default = true;
    // Values that compute what the default computes, to the bit (a faster
    // route to the same numbers: Simulator.collisionSpace 0 beside its default
    // 1). Such a value is the default to the settings digest, the checkpoint
    // origin, a run's key and a resume's comparison, so choosing it changes no
    // record of what a run computes.
    std::vector<std::string> same_result_as_default;
};

// Sections in file order.
const std::vector<std::string>& settings_sections();
// All keys, grouped by section, in file order.
const std::vector<SettingKey>& settings_table();
// nullptr when unknown.
const SettingKey* find_setting(std::string_view section, std::string_view key);
// "integer in [2, 10000000]", "one of: 0 (tournament), 1 (roulette)", ...
std::string describe_allowed(const SettingKey& k);
// Canonical text of k's default (its value in a default-constructed Settings).
std::string default_text(const SettingKey& k);
// `value` is k's default or computes what it computes (same_result_as_default).
bool computes_as_default(const SettingKey& k, const std::string& value);
// Two values of k that compute the same: equal, or both computing as the default.
bool same_result(const SettingKey& k, const std::string& a, const std::string& b);

} // namespace cic::io
