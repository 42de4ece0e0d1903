// The experiment types the settings know (experiment_types.hpp) and the
// Experiment.type key that names one.
#include "cic/io/experiment_types.hpp"

#include <algorithm>
#include <stdexcept>

#include "cic/io/settings_table.hpp"
#include "settings_values.hpp"

namespace cic::io {
namespace {

std::vector<ExperimentType>& types() {
    static std::vector<ExperimentType> t{
        {"hypergp", ExperimentFamily::HyperGP, "", "HyperGP robot control"},
        {"symreg", ExperimentFamily::Symreg, "SymbolicRegression", "symbolic regression"},
        {"gait", ExperimentFamily::Gait, "Gait", "an optimised open-loop gait (the baseline of docs/baselines.md)"},
    };
    return t;
}

std::string type_doc() {
    std::string doc = "Which experiment runs: HyperGP robot control, symbolic regression, or an optimised open-loop "
                      "gait (the baseline of docs/baselines.md). Not given: symreg when the file has a "
                      "<SymbolicRegression> section, gait when it has a <Gait> section, else hypergp (so a file of "
                      "thesis table B.1 keys runs HyperGP)";
    constexpr std::size_t kBuiltins = 3;
    for (std::size_t i = kBuiltins; i < types().size(); ++i) {
        const ExperimentType& t = types()[i];
        doc += ". Registered: " + t.name + " (" + t.doc + ", family " + std::string(to_string(t.family)) + ")";
        if (!t.section.empty()) doc += ", chosen when the file has a <" + t.section + "> section";
    }
    return doc;
}

std::vector<std::string> type_names() {
    std::vector<std::string> names;
    for (const auto& t : types()) names.push_back(t.name);
    return names;
}

} // namespace

const std::vector<ExperimentType>& experiment_types() { return types(); }

const ExperimentType* find_experiment_type(std::string_view name) {
    for (const auto& t : types())
        if (t.name == name) return &t;
    return nullptr;
}

void register_experiment_type(ExperimentType type) {
    if (!detail::valid_registered_name(type.name))
        throw std::invalid_argument("experiment type name '" + type.name +
                                    "': use 1 to 40 of a-z, 0-9, '-' and '_', starting with a letter");
    if (find_experiment_type(type.name))
        throw std::invalid_argument("experiment type '" + type.name + "' is registered twice");
    if (!type.section.empty()) {
        const auto& sections = settings_sections();
        if (std::find(sections.begin(), sections.end(), type.section) == sections.end())
            throw std::invalid_argument("experiment type '" + type.name + "': its section <" + type.section +
                                        "> has no keys (register them first: register_settings_keys)");
        for (const auto& t : types())
            if (t.section == type.section)
                throw std::invalid_argument("experiment types '" + t.name + "' and '" + type.name +
                                            "' are both selected by the section <" + type.section + ">");
    }
    types().push_back(std::move(type));
    detail::refresh_open_choice_row("Experiment", "type", type_names(), type_doc());
}

ExperimentFamily family_of(const Settings& s) {
    const ExperimentType* t = find_experiment_type(s.experiment.type);
    if (!t) throw std::invalid_argument("settings name an unknown experiment type '" + s.experiment.type + "'");
    return t->family;
}

GenotypeForm genotype_form(const Settings& s) {
    return family_of(s) == ExperimentFamily::Gait ? GenotypeForm::Vector : GenotypeForm::Trees;
}

std::string_view to_string(GenotypeForm f) { return f == GenotypeForm::Vector ? "gait vectors" : "trees"; }

bool walks_a_robot(const Settings& s) { return family_of(s) != ExperimentFamily::Symreg; }

bool evaluates_in_process(const Settings& s) { return family_of(s) == ExperimentFamily::Symreg; }

std::string_view to_string(ExperimentFamily f) {
    switch (f) {
    case ExperimentFamily::Symreg: return "symreg";
    case ExperimentFamily::HyperGP: return "hypergp";
    case ExperimentFamily::Gait: return "gait";
    }
    return "?";
}

namespace detail {

bool valid_registered_name(std::string_view n) {
    if (n.empty() || n.size() > 40 || !(n[0] >= 'a' && n[0] <= 'z')) return false;
    return std::all_of(n.begin(), n.end(),
                       [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_'; });
}

SettingKey open_choice_row(std::string section, std::string key, const std::vector<std::string>& names,
                           std::string doc, std::string& (*field)(Settings&), bool (*known)(std::string_view)) {
    SettingKey k{};
    k.section = std::move(section);
    k.key = std::move(key);
    k.type = ValueType::Enum;
    for (const auto& n : names) k.choices.push_back({n});
    k.doc = std::move(doc);
    k.get = [field](const Settings& s) { return field(const_cast<Settings&>(s)); };
    // Checked against the names known when the value is read, registrations included.
    k.set = [field, known](Settings& s, std::string_view text) {
        if (!known(text)) throw ValueError("not one of the allowed names");
        field(s) = std::string(text);
    };
    return k;
}

void refresh_open_choice_row(std::string_view section, std::string_view key, const std::vector<std::string>& names,
                             const std::string& doc) {
    if (!settings_table_built()) return;
    for (auto& k : mutable_settings_table())
        if (k.section == section && k.key == key) {
            k.choices.clear();
            for (const auto& n : names) k.choices.push_back({n});
            k.doc = doc;
        }
}

SettingKey experiment_type_row() {
    return open_choice_row("Experiment", "type", type_names(), type_doc(),
                           [](Settings& s) -> std::string& { return s.experiment.type; },
                           [](std::string_view n) { return find_experiment_type(n) != nullptr; });
}

} // namespace detail
} // namespace cic::io
