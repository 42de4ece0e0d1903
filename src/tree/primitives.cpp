#include "cic/tree/primitives.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cic::tree {

namespace {

// The inline tables in the header must follow the enum's order.
static_assert(static_cast<int>(Op::Var) + 1 == detail::kOpCount);
static_assert(detail::kArity[static_cast<int>(Op::Div)] == 2 && detail::kArity[static_cast<int>(Op::Neg)] == 1 &&
              detail::kArity[static_cast<int>(Op::Sigmoid)] == 1 && detail::kArity[static_cast<int>(Op::Const)] == 0);
static_assert(detail::kName[static_cast<int>(Op::Sigmoid)] == "sigmoid" &&
              detail::kName[static_cast<int>(Op::Var)] == "var");

constexpr std::array<Op, 15> kCanonicalFunctions{
    Op::Add, Op::Mul, Op::Atan, Op::Sin, Op::Gauss,   // the thesis's HyperGP set
    Op::Sub, Op::Div, Op::Neg, Op::Abs, Op::Cos, Op::Tanh, Op::Exp, Op::Sqrt, Op::Log, Op::Sigmoid};

constexpr std::array<double, 12> kCanonicalConstants{
    1.0, -1.0,                                         // the thesis's HyperGP constants
    0.0, 2.0, -2.0, 0.5, -0.5, 3.141592653589793, -3.141592653589793, 2.718281828459045, 0.1, -0.1};

bool finite_positive(double w) { return std::isfinite(w) && w > 0.0; }

} // namespace

void detail::throw_unknown_op(Op op) {
    throw std::invalid_argument("unknown tree operation " + std::to_string(static_cast<unsigned>(op)));
}

std::optional<Op> function_from_name(std::string_view n) {
    for (int i = 0; i < detail::kOpCount; ++i)
        if (detail::kArity[i] > 0 && detail::kName[i] == n) return static_cast<Op>(i);
    return std::nullopt;
}

std::span<const Op> canonical_functions() { return kCanonicalFunctions; }

std::span<const double> canonical_constants() { return kCanonicalConstants; }

PrimitiveSet::PrimitiveSet(PrimitiveSetConfig cfg) : cfg_(std::move(cfg)) {
    if (cfg_.functions.empty()) throw std::invalid_argument("primitive set: the function set is empty");
    for (std::size_t i = 0; i < cfg_.functions.size(); ++i) {
        const Op f = cfg_.functions[i];
        if (arity(f) == 0)
            throw std::invalid_argument("primitive set: '" + std::string(name(f)) + "' is not a function");
        if (std::find(cfg_.functions.begin(), cfg_.functions.begin() + static_cast<long>(i), f) !=
            cfg_.functions.begin() + static_cast<long>(i))
            throw std::invalid_argument("primitive set: function '" + std::string(name(f)) + "' listed twice");
    }
    if (cfg_.function_weights.empty()) cfg_.function_weights.assign(cfg_.functions.size(), 1.0);
    if (cfg_.function_weights.size() != cfg_.functions.size())
        throw std::invalid_argument("primitive set: " + std::to_string(cfg_.function_weights.size()) +
                                    " function weights for " + std::to_string(cfg_.functions.size()) +
                                    " functions");
    for (double w : cfg_.function_weights)
        if (!finite_positive(w))
            throw std::invalid_argument("primitive set: function weights must be finite and > 0, got " +
                                        std::to_string(w));
    if (cfg_.variable_count < 0 || cfg_.variable_count > 65535)
        throw std::invalid_argument("primitive set: variable count must be in [0, 65535], got " +
                                    std::to_string(cfg_.variable_count));
    for (double c : cfg_.constants)
        if (!std::isfinite(c)) throw std::invalid_argument("primitive set: constants must be finite");
    if (cfg_.ephemeral &&
        !(std::isfinite(cfg_.ephemeral_min) && std::isfinite(cfg_.ephemeral_max) &&
          cfg_.ephemeral_min < cfg_.ephemeral_max))
        throw std::invalid_argument("primitive set: ephemeral constant range must be finite with min < max");
    if (!finite_positive(cfg_.variable_weight) || !finite_positive(cfg_.constant_weight))
        throw std::invalid_argument("primitive set: terminal weights must be finite and > 0");
}

std::size_t PrimitiveSet::terminal_count() const {
    return static_cast<std::size_t>(cfg_.variable_count) + cfg_.constants.size() + (cfg_.ephemeral ? 1 : 0);
}

bool PrimitiveSet::allows(Op op) const {
    if (arity(op) == 0) return true;
    return std::find(cfg_.functions.begin(), cfg_.functions.end(), op) != cfg_.functions.end();
}

} // namespace cic::tree
