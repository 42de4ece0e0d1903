#pragma once
// The node set of GP trees: functions, variables and constants.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace cic::tree {

// Every operation a node can hold. Protected operators never produce NaN/inf
// from finite inputs; their rules are documented in docs/primitives.md.
enum class Op : std::uint8_t {
    Add, Sub, Mul, Div, Neg, Abs, Sin, Cos, Tanh, Atan, Exp, Gauss, Sqrt, Log, Sigmoid,
    Const, Var
};

int arity(Op op);
std::string_view name(Op op);                       // "add", ..., "const", "var"
std::optional<Op> function_from_name(std::string_view n);  // functions only

// The canonical order used when the thesis's functionCount picks "the first N".
// Starts with the thesis's HyperGP set: add mul atan sin gauss.
std::span<const Op> canonical_functions();
// The canonical constants used by terminalConstsCount ("the first N"): 1 -1 ...
std::span<const double> canonical_constants();

// What generators may draw from. Validated on construction (throws std::invalid_argument).
struct PrimitiveSetConfig {
    std::vector<Op> functions;              // may not be empty, no duplicates, functions only
    std::vector<double> function_weights;   // same length as functions (or empty = all 1), > 0
    int variable_count = 1;                 // >= 0; variables x0..x{n-1}
    std::vector<double> constants;          // fixed constant terminals
    bool ephemeral = false;                 // ephemeral random constants
    double ephemeral_min = -1.0, ephemeral_max = 1.0;
    double variable_weight = 1.0;           // relative weight of each variable terminal
    double constant_weight = 1.0;           // relative weight of each constant (and of the ERC slot)
};

class PrimitiveSet {
public:
    explicit PrimitiveSet(PrimitiveSetConfig cfg);
    const PrimitiveSetConfig& config() const { return cfg_; }
    int variable_count() const { return cfg_.variable_count; }
    std::size_t terminal_count() const;     // variables + constants + (ephemeral ? 1 : 0)
    bool has_terminals() const { return terminal_count() > 0; }
    bool allows(Op op) const;               // function in the set (terminals always)
private:
    PrimitiveSetConfig cfg_;
};

} // namespace cic::tree
