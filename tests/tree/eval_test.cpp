#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "cic/tree/eval.hpp"
#include "cic/tree/trig.hpp"
#include "support/random_trees.hpp"

using namespace cic;
using namespace cic::tree;

namespace {

double point(const std::string& text, std::vector<double> x) { return evaluate_point(Tree::parse(text), x); }

// Straightforward recursive evaluation with the documented rules, as the reference.
double reference(const Tree& t, std::size_t i, const std::vector<double>& x) {
    const Node& n = t.nodes()[i];
    const auto c = t.children(i);
    auto arg = [&](std::size_t k) { return reference(t, c[k], x); };
    const double big = std::numeric_limits<double>::max();
    auto clamp = [&](double v) { return std::max(-big, std::min(big, v)); };
    switch (n.op) {
    case Op::Const: return n.value;
    case Op::Var: return x[n.var];
    case Op::Add: return clamp(arg(0) + arg(1));
    case Op::Sub: return clamp(arg(0) - arg(1));
    case Op::Mul: return clamp(arg(0) * arg(1));
    case Op::Div: { const double a = arg(0), b = arg(1); return std::fabs(b) < 1e-9 ? 1.0 : clamp(a / b); }
    case Op::Neg: return -arg(0);
    case Op::Abs: return std::fabs(arg(0));
    case Op::Sin: return tree_sin(arg(0));   // trig.hpp: own kernels, std::sin beyond 1e5
    case Op::Cos: return tree_cos(arg(0));
    case Op::Tanh: return std::tanh(arg(0));
    case Op::Atan: return std::atan(arg(0));
    case Op::Exp: return std::exp(std::min(arg(0), 700.0));
    case Op::Gauss: { const double a = arg(0); return std::exp(-a * a); }
    case Op::Sqrt: return std::sqrt(std::fabs(arg(0)));
    case Op::Log: { const double a = arg(0); return a == 0.0 ? 0.0 : std::log(std::fabs(a)); }
    case Op::Sigmoid: return 1.0 / (1.0 + std::exp(std::min(-arg(0), 700.0)));
    }
    return 0.0;
}

} // namespace

TEST(Eval, EachOperationFollowsItsRule) {
    EXPECT_EQ(point("(add x0 x1)", {2, 3}), 5.0);
    EXPECT_EQ(point("(sub x0 x1)", {2, 3}), -1.0);
    EXPECT_EQ(point("(mul x0 x1)", {2, 3}), 6.0);
    EXPECT_EQ(point("(div x0 x1)", {3, 2}), 1.5);
    EXPECT_EQ(point("(neg x0)", {2}), -2.0);
    EXPECT_EQ(point("(abs x0)", {-2}), 2.0);
    EXPECT_EQ(point("(sin x0)", {0.5}), tree_sin(0.5));
    EXPECT_EQ(point("(cos x0)", {0.5}), tree_cos(0.5));
    EXPECT_EQ(point("(tanh x0)", {0.5}), std::tanh(0.5));
    EXPECT_EQ(point("(atan x0)", {0.5}), std::atan(0.5));
    EXPECT_EQ(point("(exp x0)", {0.5}), std::exp(0.5));
    EXPECT_EQ(point("(gauss x0)", {0.5}), std::exp(-0.25));
    EXPECT_EQ(point("(sqrt x0)", {4}), 2.0);
    EXPECT_EQ(point("(log x0)", {std::exp(1.0)}), 1.0);
    EXPECT_EQ(point("(sigmoid x0)", {0}), 0.5);
    EXPECT_EQ(point("2.5", {}), 2.5);
    EXPECT_EQ(point("x1", {1, 7}), 7.0);
}

TEST(Eval, ProtectedRules) {
    EXPECT_EQ(point("(div x0 x1)", {3, 0}), 1.0);
    EXPECT_EQ(point("(div x0 x1)", {3, 1e-10}), 1.0);
    EXPECT_EQ(point("(div x0 x1)", {3, -1e-10}), 1.0);
    EXPECT_EQ(point("(div x0 x1)", {1e305, 1e-8}), std::numeric_limits<double>::max());
    EXPECT_EQ(point("(sqrt x0)", {-9}), 3.0);
    EXPECT_EQ(point("(log x0)", {0}), 0.0);
    EXPECT_EQ(point("(log x0)", {-std::exp(2.0)}), 2.0);
    EXPECT_EQ(point("(exp x0)", {1e6}), std::exp(700.0));
    EXPECT_EQ(point("(add x0 x0)", {1e308}), std::numeric_limits<double>::max());
    EXPECT_EQ(point("(mul x0 x1)", {-1e300, 1e300}), -std::numeric_limits<double>::max());
    EXPECT_EQ(point("(sigmoid x0)", {-1e6}), 1.0 / (1.0 + std::exp(700.0)));
}

TEST(Eval, FiniteInputsGiveFiniteOutputs) {
    Rng rng(3);
    const std::vector<double> extremes{0.0, -0.0, 1e-320, -1e-320, 1e-9, 1e300, -1e300,
                                       std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()};
    std::vector<double> x0(extremes), x1(extremes.rbegin(), extremes.rend());
    const double* cols[] = {x0.data(), x1.data()};
    std::vector<double> out(extremes.size());
    for (int n = 0; n < 2000; ++n) {
        const Tree t = trees::random_tree(rng, 7, 2);
        evaluate(t, cols, extremes.size(), out);
        for (double v : out) ASSERT_TRUE(std::isfinite(v)) << t.to_string();
    }
}

TEST(Eval, BatchMatchesReferenceBitForBit) {
    // Blocks 0 and 2 hold ordinary values; block 1 and the partial block mix in
    // huge values, so overflow (and the clamped re-run) happens in some blocks only.
    Rng rng(11);
    const std::size_t rows = 64 * 3 + 17;
    const double extremes[] = {1e300, -1e300, 1e-300, 0.0, -0.0, 1e200, std::numeric_limits<double>::max()};
    std::vector<std::vector<double>> data(4, std::vector<double>(rows));
    for (auto& c : data)
        for (std::size_t r = 0; r < rows; ++r) {
            const bool wild = (r >= 64 && r < 128) || r >= 192;
            c[r] = wild && rng.bernoulli(0.5) ? extremes[rng.index(7)] : rng.uniform(-3.0, 3.0);
        }
    const double* cols[] = {data[0].data(), data[1].data(), data[2].data(), data[3].data()};
    std::vector<double> out(rows);
    int clamped = 0;
    for (int n = 0; n < 400; ++n) {
        const Tree t = trees::random_tree(rng, 6, 4);
        evaluate(t, cols, rows, out);
        for (std::size_t r = 0; r < rows; ++r) {
            const std::vector<double> x{data[0][r], data[1][r], data[2][r], data[3][r]};
            const double want = reference(t, t.size() - 1, x);
            ASSERT_EQ(std::bit_cast<std::uint64_t>(out[r]), std::bit_cast<std::uint64_t>(want))
                << t.to_string() << " row " << r << ": " << out[r] << " vs " << want;
            clamped += std::fabs(out[r]) == std::numeric_limits<double>::max() ? 1 : 0;
        }
    }
    EXPECT_GT(clamped, 0);   // the clamped path was exercised
}

TEST(Eval, SameTreeSameResultAcrossCallsAndRowCounts) {
    const Tree t = Tree::parse("(add (mul x0 (sin x1)) (div 1.5 (sub x0 x1)))");
    std::vector<double> a(300), b(300);
    for (std::size_t i = 0; i < a.size(); ++i) { a[i] = 0.01 * static_cast<double>(i); b[i] = 1.0 - a[i]; }
    const double* cols[] = {a.data(), b.data()};
    std::vector<double> full(300), part(5);
    evaluate(t, cols, 300, full);
    evaluate(t, cols, 5, part);
    for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(full[i], part[i]);
    std::vector<double> again(300);
    evaluate(t, cols, 300, again);
    EXPECT_EQ(full, again);
}

TEST(Eval, BadArgumentsThrow) {
    const Tree t = Tree::parse("(add x0 x2)");
    std::vector<double> c(10, 1.0), out(10);
    const double* two[] = {c.data(), c.data()};
    EXPECT_THROW(evaluate(t, two, 10, out), std::invalid_argument);
    const double* three[] = {c.data(), c.data(), c.data()};
    std::vector<double> short_out(9);
    EXPECT_THROW(evaluate(t, three, 10, short_out), std::invalid_argument);
    const double* with_null[] = {c.data(), c.data(), nullptr};
    EXPECT_THROW(evaluate(t, with_null, 10, out), std::invalid_argument);
    EXPECT_THROW(evaluate(Tree(), three, 10, out), std::invalid_argument);
    EXPECT_NO_THROW(evaluate(t, three, 0, std::span<double>()));
    EXPECT_THROW(evaluate_point(t, std::vector<double>{1.0}), std::invalid_argument);
}
