// Batch evaluation, Operon style: rows are processed in blocks of kBlock; each
// function node owns a block-sized buffer and is computed by one tight loop
// per block (one switch per node and block, none per element), which the
// compiler vectorises. Variables point straight into the caller's columns and
// constants are filled once per call, so terminals cost nothing per block.
//
// Semantics (docs/primitives.md): add/sub/mul/div results are clamped to
// +-DBL_MAX, exp/sigmoid inputs to 700, division/sqrt/log are protected; so a
// tree maps finite inputs to finite outputs.
//
// Speed: the clamps are the identity unless an infinity appears. Each block is
// first run WITHOUT clamps ("fast"); it is re-run with clamps only when an
// infinity or NaN may have occurred. Exactness argument: in the fast run a
// non-finite value at a node flows only to its parent, and every operation
// either passes non-finite values on (add sub mul neg abs sin cos sqrt log, and
// div's numerator unless the denominator is tiny, where both runs give 1) or
// is checked for non-finite input (div's denominator, exp gauss tanh atan
// sigmoid). So if no check fires and the root block is finite, no value was
// ever non-finite, every clamp was the identity, and the fast result is the
// clamped result bit for bit.
#include "cic/tree/eval.hpp"
#include "cic/tree/trig.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace cic::tree {

namespace {

constexpr std::size_t kBlock = 64;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kExpLimit = 700.0;   // exp(700) ~ 1e304, still finite
constexpr double kDivEpsilon = 1e-9;
constexpr std::uint64_t kAll = ~std::uint64_t{0};

// +-inf -> +-DBL_MAX: the largest finite double is the bit pattern just below
// infinity, so subtracting one from the bits of an infinity clamps it (a compare,
// an and and an integer add once vectorised). Finite values pass unchanged.
inline double finite(double x) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
    return std::bit_cast<double>(bits + (std::fabs(x) == kInf ? kAll : 0));
}

template <bool Clamp>
inline double fin(double x) {
    if constexpr (Clamp) return finite(x);
    else return x;
}

// Mask of all ones when x is inf or NaN (a vectorisable compare).
inline std::uint64_t non_finite(double x) { return std::fabs(x) < kInf ? 0 : kAll; }

// The per-operation loops. `n` is a compile-time constant for full blocks.
// `bad` collects the fast run's checks (see the top of the file).
#define CIC_BINARY(fname, expr, check)                                                                       \
    template <bool C>                                                                                        \
    inline void fname(double* __restrict d, const double* __restrict a, const double* __restrict b,          \
                      std::size_t n, std::uint64_t& bad) {                                                   \
        std::uint64_t acc = 0;                                                                               \
        _Pragma("GCC unroll 4") for (std::size_t k = 0; k < n; ++k) {                                        \
            const double x = a[k], y = b[k];                                                                 \
            d[k] = (expr);                                                                                   \
            if constexpr (!C) acc |= (check);                                                                \
        }                                                                                                    \
        bad |= acc;                                                                                          \
    }
#define CIC_UNARY(fname, expr, check)                                                                        \
    template <bool C>                                                                                        \
    inline void fname(double* __restrict d, const double* __restrict a, std::size_t n, std::uint64_t& bad) { \
        std::uint64_t acc = 0;                                                                               \
        for (std::size_t k = 0; k < n; ++k) {                                                                \
            const double x = a[k];                                                                           \
            d[k] = (expr);                                                                                   \
            if constexpr (!C) acc |= (check);                                                                \
        }                                                                                                    \
        bad |= acc;                                                                                          \
    }

CIC_BINARY(k_add, fin<C>(x + y), 0)
CIC_BINARY(k_sub, fin<C>(x - y), 0)
CIC_BINARY(k_mul, fin<C>(x * y), 0)
// Protected division: 1 where |y| < kDivEpsilon, else the quotient. The quotient
// is computed for every lane and the choice made with bit masks: a ?: around a
// division (which may trap, for the compiler) is not if-converted, and then the
// loop is not vectorised.
inline double div_select(double y, double q) {
    const std::uint64_t tiny = std::fabs(y) < kDivEpsilon ? kAll : 0;
    return std::bit_cast<double>((std::bit_cast<std::uint64_t>(q) & ~tiny) |
                                 (std::bit_cast<std::uint64_t>(1.0) & tiny));
}
CIC_BINARY(k_div, div_select(y, fin<C>(x / y)), (std::fabs(y) == kInf ? kAll : 0))
CIC_UNARY(k_neg, -x, 0)
CIC_UNARY(k_abs, std::fabs(x), 0)
// sin/cos: the branch-free kernels of trig.hpp over the block (vectorised),
// then std::sin/std::cos for the rare values outside their range.
#define CIC_TRIG(fname, kernel, fallback)                                                                    \
    template <bool C>                                                                                        \
    inline void fname(double* __restrict d, const double* __restrict a, std::size_t n, std::uint64_t&) {    \
        std::uint64_t far = 0;                                                                               \
        for (std::size_t k = 0; k < n; ++k) {                                                                \
            const double x = a[k];                                                                           \
            d[k] = kernel(x);                                                                                \
            far |= std::fabs(x) <= kTrigBound ? 0 : kAll;                                                    \
        }                                                                                                    \
        if (far != 0)                                                                                        \
            for (std::size_t k = 0; k < n; ++k)                                                              \
                if (!(std::fabs(a[k]) <= kTrigBound)) d[k] = fallback(a[k]);                                 \
    }
CIC_TRIG(k_sin, sin_kernel, std::sin)
CIC_TRIG(k_cos, cos_kernel, std::cos)
#undef CIC_TRIG
CIC_UNARY(k_tanh, std::tanh(x), non_finite(x))
CIC_UNARY(k_atan, std::atan(x), non_finite(x))
CIC_UNARY(k_exp, std::exp(x < kExpLimit ? x : kExpLimit), non_finite(x))
CIC_UNARY(k_gauss, std::exp(-(x * x)), non_finite(x))
CIC_UNARY(k_sqrt, std::sqrt(std::fabs(x)), 0)
CIC_UNARY(k_log, (x == 0.0 ? 0.0 : std::log(std::fabs(x))), 0)
CIC_UNARY(k_sigmoid, 1.0 / (1.0 + std::exp(-x < kExpLimit ? -x : kExpLimit)), non_finite(x))

#undef CIC_UNARY
#undef CIC_BINARY

// Throws unless every variable of the tree has a column (non-null when rows > 0).
// The common case is one branch-free sweep (a branch on "is this a variable"
// mispredicts often); the exact, throwing loop runs only when something is off.
void check_columns(std::span<const Node> nodes, std::span<const double* const> columns, std::size_t rows) {
    unsigned out_of_range = 0;
    for (const Node& n : nodes)
        out_of_range |= static_cast<unsigned>(n.op == Op::Var) & static_cast<unsigned>(n.var >= columns.size());
    const bool any_null = rows > 0 && std::find(columns.begin(), columns.end(), nullptr) != columns.end();
    if (out_of_range == 0 && !any_null) return;
    for (const Node& n : nodes) {
        if (n.op != Op::Var) continue;
        if (n.var >= columns.size())
            throw std::invalid_argument("evaluate: tree uses x" + std::to_string(n.var) + " but only " +
                                        std::to_string(columns.size()) + " columns were given");
        if (rows > 0 && columns[n.var] == nullptr)
            throw std::invalid_argument("evaluate: column " + std::to_string(n.var) + " is null");
    }
}

// Per-call scratch, reused across calls on the same thread.
struct Scratch {
    std::vector<double> buffers;          // `stride` values per node
    std::size_t stride = kBlock;          // kBlock, or less when there are fewer rows
    std::vector<const double*> stack;     // operands of the postfix sweep
};

// One block of rows through the whole tree, as a postfix sweep with a stack of
// operand pointers; returns a non-zero mask when the fast run (Clamp = false)
// must be redone with clamps. Node i writes its values to its own buffer (so the
// kernels never work in place and keep their __restrict). Constant buffers are
// filled in the first block only (`fill`) and reused by later blocks.
//
// A partial block (Fixed = 0: fewer than kBlock rows, e.g. symreg's 20) is run
// on a count rounded up to a multiple of 4, so that the loops vectorise (GCC's
// -O2 cost model vectorises only loops that need no scalar epilogue). When the
// count is not a multiple of 4 already, its variables are copied into scratch
// and padded with their last row, so the padding lanes repeat the last row's
// computation exactly: they raise no check that the real rows do not, and they
// never reach `out`.
template <std::size_t Fixed, bool Clamp>
std::uint64_t run_block(std::span<const Node> nodes, Scratch& s, std::span<const double* const> columns,
                        std::size_t row, std::size_t count, double* out, bool fill) {
    constexpr bool kPartial = Fixed == 0;
    const std::size_t n = kPartial ? (count + 3) & ~std::size_t{3} : Fixed;
    const std::size_t last = nodes.size() - 1;
    const double** top = s.stack.data();   // one past the top operand
    std::uint64_t bad = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const Node& node = nodes[i];
        double* d = (!kPartial && i == last) ? out : s.buffers.data() + i * s.stride;
        switch (node.op) {
        case Op::Var: {
            const double* column = columns[node.var] + row;
            if constexpr (kPartial) {
                if (n == count) {   // nothing to pad (20 rows): read the column in place
                    *top++ = column;
                    continue;
                }
                std::copy_n(column, count, d);
                std::fill(d + count, d + n, column[count - 1]);
                *top++ = d;
            } else {
                *top++ = column;
            }
            continue;
        }
        case Op::Const: {
            double* c = s.buffers.data() + i * s.stride;   // not `out`, even for a lone constant
            // A partial first block is the only block: n values are enough.
            if (fill) std::fill_n(c, kPartial ? n : s.stride, node.value);
            *top++ = c;
            continue;
        }
        case Op::Add: k_add<Clamp>(d, top[-2], top[-1], n, bad); --top; break;
        case Op::Sub: k_sub<Clamp>(d, top[-2], top[-1], n, bad); --top; break;
        case Op::Mul: k_mul<Clamp>(d, top[-2], top[-1], n, bad); --top; break;
        case Op::Div: k_div<Clamp>(d, top[-2], top[-1], n, bad); --top; break;
        case Op::Neg: k_neg<Clamp>(d, top[-1], n, bad); break;
        case Op::Abs: k_abs<Clamp>(d, top[-1], n, bad); break;
        case Op::Sin: k_sin<Clamp>(d, top[-1], n, bad); break;
        case Op::Cos: k_cos<Clamp>(d, top[-1], n, bad); break;
        case Op::Tanh: k_tanh<Clamp>(d, top[-1], n, bad); break;
        case Op::Atan: k_atan<Clamp>(d, top[-1], n, bad); break;
        case Op::Exp: k_exp<Clamp>(d, top[-1], n, bad); break;
        case Op::Gauss: k_gauss<Clamp>(d, top[-1], n, bad); break;
        case Op::Sqrt: k_sqrt<Clamp>(d, top[-1], n, bad); break;
        case Op::Log: k_log<Clamp>(d, top[-1], n, bad); break;
        case Op::Sigmoid: k_sigmoid<Clamp>(d, top[-1], n, bad); break;
        }
        top[-1] = d;
    }
    const double* result = s.stack[0];
    if (result != out) std::copy_n(result, count, out);   // a partial block, or a lone terminal
    if constexpr (!Clamp)
        for (std::size_t k = 0; k < n; ++k) bad |= non_finite(result[k]);
    return bad;
}

template <std::size_t Fixed>
void run_checked(std::span<const Node> nodes, Scratch& s, std::span<const double* const> columns,
                 std::size_t row, std::size_t count, double* out) {
    if (run_block<Fixed, false>(nodes, s, columns, row, count, out, row == 0) != 0)
        run_block<Fixed, true>(nodes, s, columns, row, count, out, false);
}

// All row blocks of one tree. Cloned for AVX2 where the compiler and CPU allow it;
// the results are identical (no FMA contraction, same libm calls).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(CIC_NO_CLONES)
__attribute__((target_clones("avx2", "default"), flatten))
#endif
void run_blocks(std::span<const Node> nodes, Scratch& s, std::span<const double* const> columns,
                std::size_t rows, double* out) {
    std::size_t row = 0;
    for (; row + kBlock <= rows; row += kBlock) run_checked<kBlock>(nodes, s, columns, row, kBlock, out + row);
    if (row < rows) run_checked<0>(nodes, s, columns, row, rows - row, out + row);
}

} // namespace

void evaluate(const Tree& t, std::span<const double* const> columns, std::size_t rows, std::span<double> out) {
    if (t.empty()) throw std::invalid_argument("evaluate: empty tree");
    if (out.size() < rows)
        throw std::invalid_argument("evaluate: output holds " + std::to_string(out.size()) + " values, need " +
                                    std::to_string(rows));
    const auto nodes = t.nodes();
    check_columns(nodes, columns, rows);
    if (rows == 0) return;
    thread_local Scratch s;
    // Small batches (symreg's 20 points) get buffers just large enough, rounded up
    // to 8 values (64 bytes), so scratch stays small.
    s.stride = rows >= kBlock ? kBlock : std::max<std::size_t>(8, (rows + 7) / 8 * 8);
    if (s.buffers.size() < nodes.size() * s.stride) s.buffers.resize(nodes.size() * s.stride);
    if (s.stack.size() < nodes.size()) s.stack.resize(nodes.size());
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
