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

std::vector<std::string> name_list() {
    std::vector<std::string> out;
    for (const auto& n : names()) out.push_back(n.name);
    return out;
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
    detail::refresh_open_choice_row("Neural", "substrate", name_list(), substrate_doc());
}

namespace detail {

SettingKey substrate_row() {
    SettingKey k = open_choice_row("Neural", "substrate", name_list(), substrate_doc(),
                                   [](Settings& s) -> std::string& { return s.neural.substrate; }, &is_substrate_name);
    k.digest_at_default = false;   // beyond the thesis: out of the digest at its default
    return k;
}

} // namespace detail
} // namespace cic::io
