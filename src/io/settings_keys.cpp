// What a settings key is, read from the table (settings_table.hpp): its type's
// name, its allowed values in words, its default, lookups, and the distance
// that suggests the nearest key to a misspelt one.
#include "cic/io/settings_table.hpp"

#include <algorithm>
#include <cctype>
#include <limits>

#include "settings_values.hpp"

namespace cic::io {

using detail::format_double;
using detail::join;
std::string_view type_name(ValueType t) {
    switch (t) {
    case ValueType::Bool: return "bool";
    case ValueType::Int: return "int";
    case ValueType::UInt64: return "uint64";
    case ValueType::Double: return "number";
    case ValueType::String: return "text";
    case ValueType::Path: return "path";
    case ValueType::Enum: return "name";
    case ValueType::NameList: return "names";
    case ValueType::DoubleList: return "numbers";
    case ValueType::IntList: return "integers";
    case ValueType::PathList: return "paths";
    }
    return "?";
}
const std::vector<std::string>& settings_sections() { return detail::mutable_settings_sections(); }

const std::vector<SettingKey>& settings_table() { return detail::mutable_settings_table(); }

const SettingKey* find_setting(std::string_view section, std::string_view key) {
    for (const auto& k : settings_table())
        if (k.section == section && k.key == key) return &k;
    return nullptr;
}

namespace {
std::string bounds_text(const SettingKey& k, std::string_view what) {
    bool integer = k.type == ValueType::Int || k.type == ValueType::IntList;
    auto format_double = [integer](double v) {
        return integer ? std::to_string(static_cast<long long>(v)) : detail::format_double(v);
    };
    constexpr double kHuge = std::numeric_limits<double>::max();
    bool has_min = k.min > -kHuge, has_max = k.max < kHuge;
    std::string s(what);
    if (has_min && has_max)
        s += std::string(" in ") + (k.min_exclusive ? "(" : "[") + format_double(k.min) + ", " + format_double(k.max) + "]";
    else if (has_min)
        s += (k.min_exclusive ? " > " : " >= ") + format_double(k.min);
    else if (has_max)
        s += " <= " + format_double(k.max);
    else if (k.type == ValueType::Double || k.type == ValueType::DoubleList)
        s = "any finite " + std::string(what);
    if (k.allow_inf) s += " or inf";
    return s;
}

std::string choices_text(const SettingKey& k) {
    std::vector<std::string> items;
    for (const auto& c : k.choices) items.push_back(join(c, "|"));
    return join(items, ", ");
}
} // namespace

std::string describe_allowed(const SettingKey& k) {
    switch (k.type) {
    case ValueType::Bool: return "0 or 1";
    case ValueType::Int: return bounds_text(k, "integer");
    case ValueType::UInt64: return "integer in [0, 18446744073709551615]";
    case ValueType::Double: return bounds_text(k, "number");
    case ValueType::String: return k.min_items == 0 ? "text (may be empty)" : "non-empty text";
    case ValueType::Path: return k.min_items == 0 ? "file path (empty = none)" : "non-empty path";
    case ValueType::Enum: return "one of: " + choices_text(k);
    case ValueType::NameList:
        return "space-separated distinct names from: " + choices_text(k);
    case ValueType::DoubleList:
        return "space-separated list of " + bounds_text(k, "numbers") + (k.min_items == 0 ? " (may be empty)" : "");
    case ValueType::IntList: {
        std::string s = "space-separated list of " + bounds_text(k, "integers");
        if (k.max_items < std::numeric_limits<std::size_t>::max())
            s += ", at most " + std::to_string(k.max_items);
        return s + (k.min_items == 0 ? " (may be empty)" : "");
    }
    case ValueType::PathList:
        return std::string("space-separated file paths, none with a space") + (k.min_items == 0 ? " (may be empty)" : "");
    }
    return {};
}

std::string default_text(const SettingKey& k) {
    static const Settings defaults{};
    return k.get(defaults);
}

bool computes_as_default(const SettingKey& k, const std::string& value) {
    return value == default_text(k) ||
           std::find(k.same_result_as_default.begin(), k.same_result_as_default.end(), value) !=
               k.same_result_as_default.end();
}

bool same_result(const SettingKey& k, const std::string& a, const std::string& b) {
    return a == b || (computes_as_default(k, a) && computes_as_default(k, b));
}

} // namespace cic::io
