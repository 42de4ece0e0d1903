#include "cic/tree/primitives.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cic::tree {

namespace {

struct OpInfo {
    Op op;
    std::string_view name;
    int arity;
};

// Indexed by the enum's value.
constexpr std::array<OpInfo, 17> kOps{{
    {Op::Add, "add", 2},   {Op::Sub, "sub", 2},   {Op::Mul, "mul", 2},     {Op::Div, "div", 2},
    {Op::Neg, "neg", 1},   {Op::Abs, "abs", 1},   {Op::Sin, "sin", 1},     {Op::Cos, "cos", 1},
    {Op::Tanh, "tanh", 1}, {Op::Atan, "atan", 1}, {Op::Exp, "exp", 1},     {Op::Gauss, "gauss", 1},
    {Op::Sqrt, "sqrt", 1}, {Op::Log, "log", 1},   {Op::Sigmoid, "sigmoid", 1},
    {Op::Const, "const", 0}, {Op::Var, "var", 0},
}};

const OpInfo& info(Op op) {
    const auto i = static_cast<std::size_t>(op);
    if (i >= kOps.size()) throw std::invalid_argument("unknown tree operation " + std::to_string(i));
    return kOps[i];
}

constexpr std::array<Op, 15> kCanonicalFunctions{
    Op::Add, Op::Mul, Op::Atan, Op::Sin, Op::Gauss,   // the thesis's HyperGP set
    Op::Sub, Op::Div, Op::Neg, Op::Abs, Op::Cos, Op::Tanh, Op::Exp, Op::Sqrt, Op::Log, Op::Sigmoid};

constexpr std::array<double, 12> kCanonicalConstants{
    1.0, -1.0,                                         // the thesis's HyperGP constants
    0.0, 2.0, -2.0, 0.5, -0.5, 3.141592653589793, -3.141592653589793, 2.718281828459045, 0.1, -0.1};

bool finite_positive(double w) { return std::isfinite(w) && w > 0.0; }

} // namespace

int arity(Op op) { return info(op).arity; }

std::string_view name(Op op) { return info(op).name; }

std::optional<Op> function_from_name(std::string_view n) {
    for (const auto& i : kOps)
        if (i.arity > 0 && i.name == n) return i.op;
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
