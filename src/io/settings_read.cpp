// Settings reader: XML file and --set overrides -> Settings, driven by the table.
#include <libxml/tree.h>

#include <algorithm>
#include <set>

#include "cic/io/settings_io.hpp"
#include "cic/io/experiment_types.hpp"
#include "cic/io/settings_table.hpp"
#include "cic/io/strict_xml.hpp"
#include "cic/io/xml.hpp"
#include "settings_values.hpp"

namespace cic::io {
namespace {

namespace fs = std::filesystem;

// One key's value as the user wrote it, and where.
struct Assignment {
    const SettingKey* key;
    std::string value;
    std::string file;
    int line = 0;
};

std::string lower(std::string_view s) {
    std::string out(s);
    for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

bool close_enough(std::string_view given, std::string_view known) {
    std::string g = lower(given), k = lower(known);
    if (g.size() >= 4 && (k.find(g) != std::string::npos || g.find(k) != std::string::npos)) return true;
    return edit_distance(given, known) <= std::max<std::size_t>(2, given.size() / 3);
}

std::string nearest_section(std::string_view given) {
    std::string best;
    std::size_t best_d = std::string::npos;
    for (const auto& s : settings_sections())
        if (auto d = edit_distance(given, s); d < best_d) best_d = d, best = s;
    return close_enough(given, best) ? best : std::string();
}

std::string unknown_section_message(std::string_view given) {
    std::string msg = "unknown section <" + std::string(given) + ">";
    if (auto near = nearest_section(given); !near.empty()) return msg + "; did you mean <" + near + ">?";
    for (const auto& k : settings_table())
        if (k.key == given) return msg + "; '" + k.key + "' is a key of <" + k.section + ">";
    return msg + "; sections are " + detail::join(settings_sections(), ", ");
}

std::string unknown_key_message(std::string_view section, std::string_view given) {
    std::string msg = "unknown key <" + std::string(section) + "> " + std::string(given);
    // The nearest key, preferring this section; a key that contains what was
    // typed (populationSize in generatedPopulationSize) counts as near.
    auto nearest = [&](bool this_section_only) -> const SettingKey* {
        const SettingKey* best = nullptr;
        std::size_t best_d = std::string::npos;
        for (const auto& k : settings_table()) {
            if (this_section_only && k.section != section) continue;
            auto d = edit_distance(given, k.key) * 2 + (k.section == section ? 0 : 1);
            bool contains = given.size() >= 4 && (lower(k.key).find(lower(given)) != std::string::npos);
            if (contains) d = std::min<std::size_t>(d, 1);
            if (d < best_d) best_d = d, best = &k;
        }
        return best && close_enough(given, best->key) ? best : nullptr;
    };
    for (const auto& k : settings_table())   // right key, wrong section
        if (k.key == given) {
            msg += "; '" + k.key + "' belongs in <" + k.section + ">";
            if (const SettingKey* here = nearest(true)) msg += ", or did you mean " + here->key + "?";
            return msg;
        }
    if (const SettingKey* best = nearest(false)) {
        if (best->section == section) return msg + "; did you mean " + best->key + "?";
        return msg + "; did you mean <" + best->section + "> " + best->key + "?";
    }
    return msg + "; run `cic settings --defaults` to see every key";
}

InputError value_error(const Assignment& a, const std::string& why) {
    return InputError("<" + a.key->section + "> " + a.key->key + " = \"" + a.value + "\": " + why +
                          " (allowed: " + describe_allowed(*a.key) + ")",
                      a.file, a.line);
}

// Unknown sections and keys, nested elements and attributes were refused by the
// strict reader (settings_format()); what is left is the file's own rules.
std::vector<Assignment> gather_document(const xml::Document& doc) {
    std::vector<Assignment> out;
    std::map<std::string, int> seen_sections;
    std::map<std::string, std::size_t> seen_keys;   // "Section.key" -> index in out
    for (const auto& sec : doc.root().children()) {
        std::string section(sec.name());
        if (auto [it, fresh] = seen_sections.emplace(section, sec.line()); !fresh)
            throw sec.error("section <" + section + "> appears twice (first at line " + std::to_string(it->second) + ")");
        for (const auto& node : sec.children()) {
            std::string key(node.name());
            const SettingKey* k = find_setting(section, key);
            // A key repeated with the same value is harmless (thesis table B.1 itself
            // lists functionProbabilities twice); with another value it is a conflict.
            if (auto [it, fresh] = seen_keys.emplace(section + "." + key, out.size()); !fresh) {
                const Assignment& first = out[it->second];
                if (xml::trim(first.value) == xml::trim(node.text())) continue;
                throw node.error("<" + section + "> " + key + " = \"" + node.text() + "\" is given twice, first as \"" +
                                 first.value + "\" at line " + std::to_string(first.line));
            }
            out.push_back({k, node.text(), node.file(), node.line()});
        }
    }
    return out;
}

std::vector<Assignment> gather_overrides(const std::vector<std::string>& overrides) {
    std::vector<Assignment> out;
    for (const auto& o : overrides) {
        auto eq = o.find('=');
        auto dot = o.find('.');
        if (eq == std::string::npos || dot == std::string::npos || dot > eq || dot == 0)
            throw InputError("expected Section.key=value, got \"" + o + "\"", "--set");
        std::string section = xml::trim(std::string_view(o).substr(0, dot));
        std::string key = xml::trim(std::string_view(o).substr(dot + 1, eq - dot - 1));
        if (std::find(settings_sections().begin(), settings_sections().end(), section) == settings_sections().end())
            throw InputError(unknown_section_message(section), "--set");
        const SettingKey* k = find_setting(section, key);
        if (!k) throw InputError(unknown_key_message(section, key), "--set");
        out.push_back({k, xml::trim(std::string_view(o).substr(eq + 1)), "--set", 0});
    }
    return out;
}

std::size_t table_index(const SettingKey* k) { return static_cast<std::size_t>(k - settings_table().data()); }

void check_item_count(const Assignment& a) {
    const SettingKey& k = *a.key;
    const bool list = is_list(k.type);
    if (a.value.empty()) {
        if (k.min_items == 0) return;
        throw value_error(a, "empty value");
    }
    if (!list) return;
    std::size_t n = 0;
    try {
        n = detail::split_items(a.value).size();
    } catch (const ValueError& e) {
        throw value_error(a, e.what());
    }
    if (n < k.min_items) throw value_error(a, "needs at least " + std::to_string(k.min_items) + " item(s)");
    if (n > k.max_items) throw value_error(a, "has " + std::to_string(n) + " items");
}

// Applies one layer (a file, or all --set overrides) in table order, so that
// counts come before names and names before weights whatever the file's order.
void apply_layer(Settings& s, std::vector<Assignment> layer, detail::Locations& locs, const fs::path* base_dir) {
    std::stable_sort(layer.begin(), layer.end(),
                     [](const Assignment& a, const Assignment& b) { return table_index(a.key) < table_index(b.key); });
    std::map<std::string, const Assignment*> given;
    for (auto& a : layer) {
        check_item_count(a);
        std::string value = a.value;
        if (a.key->type == ValueType::Path && base_dir && !value.empty() && fs::path(value).is_relative())
            value = fs::absolute(*base_dir / value).lexically_normal().string();
        if (a.key->type == ValueType::PathList && base_dir) {   // each item as a Path
            std::vector<std::string> items;
            for (auto item : detail::split_items(value))
                items.push_back(fs::path(item).is_relative()
                                    ? fs::absolute(*base_dir / item).lexically_normal().string()
                                    : std::string(item));
            value = detail::join(items);
        }
        try {
            a.key->set(s, value);
        } catch (const ValueError& e) {
            throw value_error(a, e.what());
        }
        given[a.key->key] = &a;
        locs[a.key->section + "." + a.key->key] = {a.file, a.line};
    }
    // The thesis's counts and our name lists must agree when both are given.
    auto& p = s.gp.primitives;
    auto agree = [&](const char* count_key, const char* list_key, std::size_t n, const char* what) {
        if (!given.count(count_key) || !given.count(list_key)) return;
        const Assignment& a = *given[count_key];
        if (std::to_string(n) != xml::trim(a.value))
            throw InputError("<GP> " + std::string(count_key) + " = \"" + a.value + "\" does not match the " +
                                 std::to_string(n) + " " + what + " in " + list_key,
                             a.file, a.line);
    };
    agree("functionCount", "functions", p.functions.size(), "names");
    agree("terminalConstsCount", "terminalConsts", p.constants.size(), "values");
    // A new function set without its own weights gets equal weights.
    bool set_changed = given.count("functionCount") || given.count("functions");
    if (set_changed && !given.count("functionProbabilities") && p.function_weights.size() != p.functions.size())
        p.function_weights.assign(p.functions.size(), 1.0);
}

// Experiment.type when the file does not give it: the type whose own section
// the file has (<SymbolicRegression>: symreg, <Gait>: gait, a registered
// type's section: that type), anything else HyperGP (docs/settings.md).
void infer_experiment_type(Settings& s, const xml::Document& doc) {
    for (const auto& sec : doc.root().children())
        for (const auto& t : experiment_types())
            if (!t.section.empty() && sec.name() == t.section) s.experiment.type = t.name;
}

} // namespace

const xml::Format& settings_format() {
    static const xml::Format f{
        "settings",
        "settings file",
        [] { return settings_schema(); },
        [](const xml::Node& parent, std::string_view element) -> std::optional<std::string> {
            const _xmlNode* up = parent.get()->parent;
            if (up && up->type == XML_DOCUMENT_NODE) return unknown_section_message(element);
            if (up && up->parent && up->parent->type == XML_DOCUMENT_NODE)
                return unknown_key_message(parent.name(), element);
            return "<" + std::string(reinterpret_cast<const char*>(up->name)) + "> " + std::string(parent.name()) +
                   ": expected a value, found nested elements";
        },
        [](const xml::Node& element, std::string_view) -> std::optional<std::string> {
            const _xmlNode* up = element.get()->parent;
            if (!up || !up->parent || up->parent->type != XML_ELEMENT_NODE) return std::nullopt;
            const std::string key(element.name());
            return "<" + std::string(reinterpret_cast<const char*>(up->name)) + "> " + key +
                   ": write the value as the element's text, <" + key + ">value</" + key + ">, not as an attribute";
        }};
    return f;
}

Settings load_settings(const fs::path& file, const std::vector<std::string>& overrides) {
    if (file.empty()) return load_settings_text({}, {}, overrides);
    return load_settings_text(xml::read_file(file), file, overrides);
}

Settings load_settings_text(std::string_view text, const fs::path& file, const std::vector<std::string>& overrides) {
    Settings s;
    detail::Locations locs;
    if (!file.empty()) {
        const fs::path base = fs::absolute(file).parent_path();
        xml::read_strict(text, file.string(), settings_format(), [&](const xml::Document& doc) {
            infer_experiment_type(s, doc);
            apply_layer(s, gather_document(doc), locs, &base);
            return 0;
        });
        s.source_file = file.string();
    }
    // Paths on the command line are relative to the current folder; every path is
    // stored absolute, so workers, replays and resumes find the same file.
    const fs::path cwd = fs::current_path();
    apply_layer(s, gather_overrides(overrides), locs, &cwd);
    detail::validate(s, locs);
    for (const auto& [key, where] : locs) s.key_locations[key] = {where.file, where.line};
    return s;
}

InputError key_error(const Settings& s, const std::vector<std::string>& keys, const std::string& message) {
    std::pair<std::string, int> where{s.source_file, 0};
    for (const auto& k : keys)
        if (const auto it = s.key_locations.find(k); it != s.key_locations.end()) {
            where = it->second;
            break;
        }
    std::string named;
    for (const auto& k : keys) {
        const auto dot = k.find('.');
        const SettingKey* row = find_setting(k.substr(0, dot), k.substr(dot + 1));
        named += (named.empty() ? "" : ", ") + ("<" + k.substr(0, dot) + "> " + k.substr(dot + 1) + " = \"" +
                                               (row ? row->get(s) : std::string("?")) + "\"");
    }
    return InputError(named + ": " + message, where.first, where.second);
}

Settings read_settings(const fs::path& file) { return load_settings(file, {}); }

Settings read_settings_string(std::string_view text, const std::string& name) {
    Settings s;
    detail::Locations locs;
    xml::read_strict(text, name, settings_format(), [&](const xml::Document& doc) {
        infer_experiment_type(s, doc);
        apply_layer(s, gather_document(doc), locs, nullptr);
        return 0;
    });
    s.source_file = name;
    detail::validate(s, locs);
    for (const auto& [key, where] : locs) s.key_locations[key] = {where.file, where.line};
    return s;
}

void validate_settings(const Settings& s) { detail::validate(s, {}); }

} // namespace cic::io
