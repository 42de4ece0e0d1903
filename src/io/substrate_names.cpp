// The names Neural.substrate accepts (substrate_names.hpp) and its row.
#include "cic/io/substrate_names.hpp"

#include <stdexcept>

#include "cic/io/settings_table.hpp"
#include "settings_values.hpp"

namespace cic::io {
namespace {

constexpr std::size_t kBuiltins = 3;

std::vector<SubstrateName>& names() {
    static std::vector<SubstrateName> n{
        {"network", "the thesis's recurrent network"},
        {"cpg", "coupled oscillators, one per joint"},
        {"gait", "each joint's amplitude, phase and offset, one evolved frequency"},
    };
    return n;
}

std::string substrate_doc() {
    std::string doc = "What the genotype is queried to build: network (the thesis's recurrent network), cpg (coupled "
                      "oscillators, one per joint) or gait (each joint's amplitude, phase and offset, one evolved "
                      "frequency)";
    for (std::size_t i = kBuiltins; i < names().size(); ++i)
        doc += ". Registered: " + names()[i].name + " (" + names()[i].doc + ")";
    return doc;
}

} // namespace

const std::vector<SubstrateName>& substrate_names() { return names(); }

bool is_substrate_name(std::string_view name) {
    for (const auto& n : names())
        if (n.name == name) return true;
    return false;
}

void register_substrate_name(SubstrateName name) {
    if (!detail::valid_registered_name(name.name))
        throw std::invalid_argument("substrate name '" + name.name +
                                    "': use 1 to 40 of a-z, 0-9, '-' and '_', starting with a letter");
    if (is_substrate_name(name.name)) throw std::invalid_argument("substrate '" + name.name + "' is registered twice");
    names().push_back(std::move(name));
    for (auto& k : detail::mutable_settings_table())
        if (k.section == "Neural" && k.key == "substrate") {
            k.choices.push_back({names().back().name});
            k.doc = substrate_doc();
        }
}

namespace detail {

SettingKey substrate_row() {
    SettingKey k{};
    k.section = "Neural";
    k.key = "substrate";
    k.type = ValueType::Enum;
    for (const auto& n : names()) k.choices.push_back({n.name});
    k.doc = substrate_doc();
    k.digest_at_default = false;   // beyond the thesis: out of the digest at its default
    k.get = [](const Settings& s) { return s.neural.substrate; };
    // Checked against the names known when the value is read, registrations included.
    k.set = [](Settings& s, std::string_view text) {
        if (!is_substrate_name(text)) throw ValueError("not one of the allowed names");
        s.neural.substrate = std::string(text);
    };
    return k;
}

} // namespace detail
} // namespace cic::io
