// Keys that registered experiment types bring (settings_extension.hpp).
#include "cic/io/settings_extension.hpp"

#include <algorithm>
#include <stdexcept>

#include "settings_values.hpp"

namespace cic::io {
namespace {

std::string id_of(std::string_view section, std::string_view key) {
    return std::string(section) + "." + std::string(key);
}

// A key whose value is kept in Settings::extra as canonical text.
SettingKey extra_key(std::string section, std::string key, ValueType type, std::string doc, std::string default_text) {
    SettingKey k{};
    k.section = std::move(section);
    k.key = std::move(key);
    k.type = type;
    k.doc = std::move(doc);
    k.digest_at_default = false;   // a key added later leaves the digests of older runs alone
    const std::string id = id_of(k.section, k.key);
    k.get = [id, default_text](const Settings& s) {
        auto it = s.extra.find(id);
        return it == s.extra.end() ? default_text : it->second;
    };
    return k;
}

// `canonical` parses and checks the text (throwing ValueError) and returns its canonical form.
void attach_setter(SettingKey& k, std::function<std::string(const SettingKey&, std::string_view)> canonical) {
    const SettingKey bounds = k;
    const std::string id = id_of(k.section, k.key);
    k.set = [id, bounds, canonical](Settings& s, std::string_view text) { s.extra[id] = canonical(bounds, text); };
}

const SettingKey& registered(std::string_view section, std::string_view key, ValueType type) {
    const SettingKey* k = find_setting(section, key);
    if (!k || k->type != type)
        throw std::invalid_argument("no registered " + std::string(type_name(type)) + " key <" +
                                    std::string(section) + "> " + std::string(key));
    return *k;
}

bool is_builtin_section(std::string_view section) {
    const auto& builtin = detail::builtin_settings_sections();
    return std::find(builtin.begin(), builtin.end(), section) != builtin.end();
}

} // namespace

SettingKey extra_number_key(std::string section, std::string key, double default_value, double min, double max,
                            std::string doc) {
    auto k = extra_key(std::move(section), std::move(key), ValueType::Double, std::move(doc),
                       detail::format_double(default_value));
    k.min = min;
    k.max = max;
    attach_setter(k, [](const SettingKey& b, std::string_view t) {
        return detail::format_double(detail::parse_number(b, t));
    });
    return k;
}

SettingKey extra_integer_key(std::string section, std::string key, long long default_value, long long min,
                             long long max, std::string doc) {
    auto k = extra_key(std::move(section), std::move(key), ValueType::Int, std::move(doc),
                       std::to_string(default_value));
    k.min = static_cast<double>(min);
    k.max = static_cast<double>(max);
    attach_setter(k, [](const SettingKey& b, std::string_view t) { return std::to_string(detail::parse_integer(b, t)); });
    return k;
}

SettingKey extra_choice_key(std::string section, std::string key, std::vector<std::string> choices,
                            std::string default_value, std::string doc) {
    if (std::find(choices.begin(), choices.end(), default_value) == choices.end())
        throw std::invalid_argument("<" + section + "> " + key + ": the default '" + default_value +
                                    "' is not one of its choices");
    auto k = extra_key(std::move(section), std::move(key), ValueType::Enum, std::move(doc), default_value);
    for (auto& c : choices) k.choices.push_back({c});
    attach_setter(k, [](const SettingKey& b, std::string_view t) { return b.choices[detail::parse_choice(b, t)].front(); });
    return k;
}

void register_settings_keys(std::vector<SettingKey> keys) {
    auto& table = detail::mutable_settings_table();
    auto& sections = detail::mutable_settings_sections();
    for (auto& k : keys) {
        if (is_builtin_section(k.section))
            throw std::invalid_argument("<" + k.section + "> " + k.key +
                                        ": a registered key needs a section of its own, not a built-in one");
        if (find_setting(k.section, k.key))
            throw std::invalid_argument("<" + k.section + "> " + k.key + " is registered twice");
        if (!k.get || !k.set || k.digest_at_default)
            throw std::invalid_argument("<" + k.section + "> " + k.key + ": make registered keys with extra_*_key");
        if (std::find(sections.begin(), sections.end(), k.section) == sections.end()) sections.push_back(k.section);
        // Keep a section's keys together: after its last key, else at the end.
        auto last = std::find_if(table.rbegin(), table.rend(), [&](const SettingKey& t) { return t.section == k.section; });
        if (last == table.rend()) table.push_back(std::move(k));
        else table.insert(last.base(), std::move(k));
    }
}

double extra_number(const Settings& s, std::string_view section, std::string_view key) {
    const SettingKey& k = registered(section, key, ValueType::Double);
    return detail::parse_number(k, k.get(s));
}

long long extra_integer(const Settings& s, std::string_view section, std::string_view key) {
    const SettingKey& k = registered(section, key, ValueType::Int);
    return detail::parse_integer(k, k.get(s));
}

std::string extra_choice(const Settings& s, std::string_view section, std::string_view key) {
    return registered(section, key, ValueType::Enum).get(s);
}

} // namespace cic::io
