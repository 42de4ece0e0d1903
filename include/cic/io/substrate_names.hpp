#pragma once
// The names the Neural.substrate key accepts: the three built-in controllers
// (network, cpg, gait) and those a controller registration adds
// (hypergp::register_controller, docs/extending.md).
#include <string>
#include <string_view>
#include <vector>

namespace cic::io {

struct SubstrateName {
    std::string name;   // lower case, digits, '-' or '_'
    std::string doc;    // one line
};

// Built-ins first, then registrations in their order.
const std::vector<SubstrateName>& substrate_names();
bool is_substrate_name(std::string_view name);
// Adds a name; the Neural.substrate key accepts it from then on. Register
// before reading settings. Throws std::invalid_argument for a bad or taken name.
void register_substrate_name(SubstrateName name);

} // namespace cic::io
