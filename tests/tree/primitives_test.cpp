#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "cic/tree/primitives.hpp"

using namespace cic::tree;

TEST(Primitives, NamesAndAritiesRoundTrip) {
    for (Op f : canonical_functions()) {
        ASSERT_GT(arity(f), 0);
        auto back = function_from_name(name(f));
        ASSERT_TRUE(back.has_value()) << name(f);
        EXPECT_EQ(*back, f);
    }
    EXPECT_EQ(arity(Op::Add), 2);
    EXPECT_EQ(arity(Op::Div), 2);
    EXPECT_EQ(arity(Op::Gauss), 1);
    EXPECT_EQ(arity(Op::Const), 0);
    EXPECT_EQ(arity(Op::Var), 0);
    EXPECT_FALSE(function_from_name("const").has_value());
    EXPECT_FALSE(function_from_name("var").has_value());
    EXPECT_FALSE(function_from_name("pow").has_value());
    EXPECT_THROW(arity(static_cast<Op>(200)), std::invalid_argument);
}

TEST(Primitives, CanonicalOrderStartsWithThesisSet) {
    const auto fs = canonical_functions();
    ASSERT_EQ(fs.size(), 15u);
    const Op thesis[] = {Op::Add, Op::Mul, Op::Atan, Op::Sin, Op::Gauss, Op::Sub, Op::Div, Op::Neg,
                         Op::Abs, Op::Cos, Op::Tanh, Op::Exp, Op::Sqrt, Op::Log, Op::Sigmoid};
    for (std::size_t i = 0; i < fs.size(); ++i) EXPECT_EQ(fs[i], thesis[i]) << i;
    const auto cs = canonical_constants();
    ASSERT_GE(cs.size(), 8u);
    EXPECT_EQ(cs[0], 1.0);
    EXPECT_EQ(cs[1], -1.0);
    EXPECT_EQ(cs[2], 0.0);
}

TEST(Primitives, SetValidatesAndFillsWeights) {
    PrimitiveSet ps({{Op::Add, Op::Sin}, {}, 3, {1.0, -1.0}, true, -2.0, 2.0});
    EXPECT_EQ(ps.config().function_weights.size(), 2u);
    EXPECT_EQ(ps.terminal_count(), 3u + 2u + 1u);
    EXPECT_TRUE(ps.allows(Op::Add));
    EXPECT_FALSE(ps.allows(Op::Mul));
    EXPECT_TRUE(ps.allows(Op::Var));
    EXPECT_TRUE(ps.has_terminals());
    EXPECT_FALSE(PrimitiveSet({{Op::Add}, {}, 0, {}}).has_terminals());
}

TEST(Primitives, SetRejectsBadConfig) {
    EXPECT_THROW(PrimitiveSet({{}, {}, 1, {}}), std::invalid_argument);
    EXPECT_THROW(PrimitiveSet({{Op::Add, Op::Add}, {}, 1, {}}), std::invalid_argument);
    EXPECT_THROW(PrimitiveSet({{Op::Const}, {}, 1, {}}), std::invalid_argument);
    EXPECT_THROW(PrimitiveSet({{Op::Add}, {1, 2}, 1, {}}), std::invalid_argument);
    EXPECT_THROW(PrimitiveSet({{Op::Add}, {0}, 1, {}}), std::invalid_argument);
    EXPECT_THROW(PrimitiveSet({{Op::Add}, {-1}, 1, {}}), std::invalid_argument);
    EXPECT_THROW(PrimitiveSet({{Op::Add}, {}, -1, {}}), std::invalid_argument);
    EXPECT_THROW(PrimitiveSet({{Op::Add}, {}, 1, {std::numeric_limits<double>::infinity()}}), std::invalid_argument);
    EXPECT_THROW(PrimitiveSet({{Op::Add}, {}, 1, {}, true, 1.0, 1.0}), std::invalid_argument);
    PrimitiveSetConfig c{{Op::Add}, {}, 1, {}};
    c.variable_weight = 0.0;
    EXPECT_THROW(PrimitiveSet{c}, std::invalid_argument);
}
