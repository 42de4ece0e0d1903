// Batch evaluation, Operon style: rows are processed in blocks of kBlock; each
// function node owns a block-sized buffer and is computed by one tight loop
// per block (one switch per node and block, none per element), which the
// compiler vectorises. Variables point straight into the caller's columns and
// constants are filled once per call, so terminals cost nothing per block.
//
// Every operation maps finite inputs to finite outputs (docs/primitives.md):
// add/sub/mul/div clamp to +-DBL_MAX, exp-like inputs are clamped, protected
// division/sqrt/log have fixed rules. Hence a whole tree is finite on finite input.
#include "cic/tree/eval.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace cic::tree {

namespace {

constexpr std::size_t kBlock = 64;
constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kExpLimit = 700.0;   // exp(700) ~ 1e304, still finite
constexpr double kDivEpsilon = 1e-9;

// Written as compare-selects so they map onto minpd/maxpd.
inline double finite(double x) {
    x = x < kMax ? x : kMax;
    return x > -kMax ? x : -kMax;
}

// The per-operation loops. `n` is a compile-time constant for full blocks.
#define CIC_UNARY(name, expr)                                                                  \
    inline void name(double* __restrict d, const double* __restrict a, std::size_t n) {        \
        for (std::size_t k = 0; k < n; ++k) {                                                  \
            const double x = a[k];                                                             \
            d[k] = (expr);                                                                     \
        }                                                                                      \
    }
#define CIC_BINARY(name, expr)                                                                                    \
    inline void name(double* __restrict d, const double* __restrict a, const double* __restrict b, std::size_t n) { \
        for (std::size_t k = 0; k < n; ++k) {                                                                     \
            const double x = a[k], y = b[k];                                                                      \
            d[k] = (expr);                                                                                        \
        }                                                                                                         \
    }

CIC_BINARY(k_add, finite(x + y))
CIC_BINARY(k_sub, finite(x - y))
CIC_BINARY(k_mul, finite(x * y))
// The quotient is computed unconditionally so the select is branch-free.
CIC_BINARY(k_div, (std::fabs(y) < kDivEpsilon ? 1.0 : finite(x / y)))
CIC_UNARY(k_neg, -x)
CIC_UNARY(k_abs, std::fabs(x))
CIC_UNARY(k_sin, std::sin(x))
CIC_UNARY(k_cos, std::cos(x))
CIC_UNARY(k_tanh, std::tanh(x))
CIC_UNARY(k_atan, std::atan(x))
CIC_UNARY(k_exp, std::exp(x < kExpLimit ? x : kExpLimit))
CIC_UNARY(k_gauss, std::exp(-(x * x)))
CIC_UNARY(k_sqrt, std::sqrt(std::fabs(x)))
CIC_UNARY(k_log, (x == 0.0 ? 0.0 : std::log(std::fabs(x))))
CIC_UNARY(k_sigmoid, 1.0 / (1.0 + std::exp(-x < kExpLimit ? -x : kExpLimit)))

#undef CIC_UNARY
#undef CIC_BINARY

// Per-call scratch, reused across calls on the same thread.
struct Scratch {
    std::vector<double> buffers;          // kBlock values per node
    std::vector<const double*> value;     // where node i's values for the current block are
    std::vector<std::uint32_t> first;     // first child of node i
};

template <std::size_t Fixed>
void run_block(std::span<const Node> nodes, Scratch& s, std::span<const double* const> columns,
               std::size_t row, std::size_t count, double* out) {
    const std::size_t n = Fixed ? Fixed : count;
    const std::size_t last = nodes.size() - 1;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const Node& node = nodes[i];
        double* d = i == last ? out : s.buffers.data() + i * kBlock;
        const double* a = s.value[s.first[i]];
        const double* b = s.value[i == 0 ? 0 : i - 1];   // second child of a binary node
        switch (node.op) {
        case Op::Var: s.value[i] = columns[node.var] + row; continue;
        case Op::Const: s.value[i] = s.buffers.data() + i * kBlock; continue;
        case Op::Add: k_add(d, a, b, n); break;
        case Op::Sub: k_sub(d, a, b, n); break;
        case Op::Mul: k_mul(d, a, b, n); break;
        case Op::Div: k_div(d, a, b, n); break;
        case Op::Neg: k_neg(d, a, n); break;
        case Op::Abs: k_abs(d, a, n); break;
        case Op::Sin: k_sin(d, a, n); break;
        case Op::Cos: k_cos(d, a, n); break;
        case Op::Tanh: k_tanh(d, a, n); break;
        case Op::Atan: k_atan(d, a, n); break;
        case Op::Exp: k_exp(d, a, n); break;
        case Op::Gauss: k_gauss(d, a, n); break;
        case Op::Sqrt: k_sqrt(d, a, n); break;
        case Op::Log: k_log(d, a, n); break;
        case Op::Sigmoid: k_sigmoid(d, a, n); break;
        }
        s.value[i] = d;
    }
    if (nodes[last].op == Op::Var || nodes[last].op == Op::Const)   // a lone terminal
        std::copy_n(s.value[last], n, out);
}

// All row blocks of one tree. Cloned for AVX2 where the compiler and CPU allow it;
// the results are identical (no FMA contraction, same libm calls).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(CIC_NO_CLONES)
__attribute__((target_clones("avx2", "default"), flatten))
#endif
void run_blocks(std::span<const Node> nodes, Scratch& s, std::span<const double* const> columns,
                std::size_t rows, double* out) {
    std::size_t row = 0;
    for (; row + kBlock <= rows; row += kBlock) run_block<kBlock>(nodes, s, columns, row, kBlock, out + row);
    if (row < rows) run_block<0>(nodes, s, columns, row, rows - row, out + row);
}

} // namespace

void evaluate(const Tree& t, std::span<const double* const> columns, std::size_t rows, std::span<double> out) {
    if (t.empty()) throw std::invalid_argument("evaluate: empty tree");
    if (out.size() < rows)
        throw std::invalid_argument("evaluate: output holds " + std::to_string(out.size()) + " values, need " +
                                    std::to_string(rows));
    const auto nodes = t.nodes();
    thread_local Scratch s;
    s.buffers.resize(nodes.size() * kBlock);
    s.value.assign(nodes.size(), nullptr);
    s.first.resize(nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const Node& n = nodes[i];
        if (n.op == Op::Var) {
            if (n.var >= columns.size())
                throw std::invalid_argument("evaluate: tree uses x" + std::to_string(n.var) + " but only " +
                                            std::to_string(columns.size()) + " columns were given");
            if (rows > 0 && columns[n.var] == nullptr)
                throw std::invalid_argument("evaluate: column " + std::to_string(n.var) + " is null");
        } else if (n.op == Op::Const) {
            std::fill_n(s.buffers.data() + i * kBlock, kBlock, n.value);
        }
        const int a = arity(n.op);
        // First child: for unary i-1, for binary skip the second child's subtree.
        s.first[i] = a == 0 ? 0 : a == 1 ? static_cast<std::uint32_t>(i - 1)
                                         : static_cast<std::uint32_t>(i - 1 - nodes[i - 1].size);
    }
    if (rows == 0) return;
    run_blocks(nodes, s, columns, rows, out.data());
}

double evaluate_point(const Tree& t, std::span<const double> x) {
    std::vector<const double*> columns(x.size());
    for (std::size_t v = 0; v < x.size(); ++v) columns[v] = &x[v];
    double out = 0.0;
    evaluate(t, columns, 1, std::span<double>(&out, 1));
    return out;
}

} // namespace cic::tree
