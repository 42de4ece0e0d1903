// The infix target parser: values, precedence, variables and error columns.
#include <cmath>
#include <numbers>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cic/core/error.hpp"
#include "cic/experiments/symreg/expression.hpp"

using cic::InputError;
using cic::symreg::Expression;
using testing::HasSubstr;

namespace {

double eval(const char* text, std::vector<double> x = {0.0}) {
    return Expression::parse(text).evaluate(x);
}

std::string error_of(const char* text) {
    try {
        Expression::parse(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

} // namespace

TEST(SymregExpression, ArithmeticMatchesHandValues) {
    EXPECT_DOUBLE_EQ(eval("1 + 2"), 3.0);
    EXPECT_DOUBLE_EQ(eval("10 - 4 - 3"), 3.0);    // left-associative
    EXPECT_DOUBLE_EQ(eval("8 / 4 / 2"), 1.0);
    EXPECT_DOUBLE_EQ(eval("(2 + 3) * 4"), 20.0);
    EXPECT_DOUBLE_EQ(eval("1e-3 * 1000"), 1.0);
    EXPECT_DOUBLE_EQ(eval(".5 + 2.5E+1"), 25.5);
    EXPECT_DOUBLE_EQ(eval("pi"), std::numbers::pi);
    EXPECT_DOUBLE_EQ(eval("2**3"), 8.0);
}

TEST(SymregExpression, PrecedenceAsInMathematics) {
    EXPECT_DOUBLE_EQ(eval("2+3*4^2"), 50.0);
    EXPECT_DOUBLE_EQ(eval("-2^2"), -4.0);          // unary minus binds looser than ^
    EXPECT_DOUBLE_EQ(eval("2^-1"), 0.5);
    EXPECT_DOUBLE_EQ(eval("2^3^2"), 512.0);        // right-associative
    EXPECT_DOUBLE_EQ(eval("-x^2", {3.0}), -9.0);
    EXPECT_DOUBLE_EQ(eval("--3"), 3.0);
    EXPECT_DOUBLE_EQ(eval("2*-3"), -6.0);
}

TEST(SymregExpression, FunctionsAndVariables) {
    const std::vector<double> x{0.5, 0.25, 2.0};
    EXPECT_DOUBLE_EQ(eval("sin(x) + cos(y)", x), std::sin(0.5) + std::cos(0.25));
    EXPECT_DOUBLE_EQ(eval("x0*x1*x2", x), 0.25);
    EXPECT_DOUBLE_EQ(eval("z", x), 2.0);
    EXPECT_DOUBLE_EQ(eval("exp(log(z)) + sqrt(4) + abs(-y) + atan(0) + tanh(0) + tan(0)", x), 4.25);
    EXPECT_DOUBLE_EQ(eval("x^4 + x^3 + x^2 + x", {0.5}), 0.9375);
    EXPECT_EQ(Expression::parse("3").variables(), 1);
    EXPECT_EQ(Expression::parse("y").variables(), 2);
    EXPECT_EQ(Expression::parse("x0 + x9").variables(), 10);
}

TEST(SymregExpression, ErrorsNameTheColumnAndWhatWasExpected) {
    EXPECT_THAT(error_of("2+"), HasSubstr("column 3: expected a number"));
    EXPECT_THAT(error_of("x^"), HasSubstr("column 3"));
    EXPECT_THAT(error_of("(x+1"), HasSubstr("column 5: expected ')'"));
    EXPECT_THAT(error_of("foo(x)"), HasSubstr("column 1: unknown name 'foo'"));
    EXPECT_THAT(error_of("2x"), HasSubstr("column 1: malformed number"));
    EXPECT_THAT(error_of("x $ 2"), HasSubstr("column 3: expected an operator"));
    EXPECT_THAT(error_of("sin x"), HasSubstr("column 5: expected '(' after function sin"));
    EXPECT_THAT(error_of(""), HasSubstr("empty"));
    EXPECT_THAT(error_of("x10"), HasSubstr("unknown name 'x10'"));
    EXPECT_THAT(error_of(std::string(500, '(').c_str()), HasSubstr("nested too deeply"));
}

TEST(SymregExpression, EvaluateNeedsEveryVariable) {
    const auto e = Expression::parse("x + y");
    const std::vector<double> one{1.0};
    EXPECT_THROW(e.evaluate(one), std::invalid_argument);
}

TEST(SymregExpression, SameTextSameValue) {
    const std::vector<double> x{0.3};
    const double a = eval("sin(x)^2 + cos(x)^2 - x/7", x);
    const double b = eval("sin(x)^2 + cos(x)^2 - x/7", x);
    EXPECT_EQ(a, b);
}
