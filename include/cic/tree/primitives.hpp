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

namespace detail {
inline constexpr int kOpCount = 17;
// Indexed by the enum's value; inline because arity() sits in every tree walk.
inline constexpr std::int8_t kArity[kOpCount] = {2, 2, 2, 2, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 0};
inline constexpr std::string_view kName[kOpCount] = {
    "add", "sub", "mul", "div", "neg", "abs", "sin", "cos", "tanh", "atan", "exp", "gauss", "sqrt", "log", "sigmoid",
    "const", "var"};
[[noreturn]] void throw_unknown_op(Op op);   // std::invalid_argument
} // namespace detail

// Number of children; throws std::invalid_argument for a value outside the enum.
inline int arity(Op op) {
    const auto i = static_cast<unsigned>(op);
    if (i >= static_cast<unsigned>(detail::kOpCount)) [[unlikely]] detail::throw_unknown_op(op);
    return detail::kArity[i];
}
// "add", ..., "const", "var"; throws std::invalid_argument like arity().
inline std::string_view name(Op op) {
    const auto i = static_cast<unsigned>(op);
    if (i >= static_cast<unsigned>(detail::kOpCount)) [[unlikely]] detail::throw_unknown_op(op);
    return detail::kName[i];
}
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
