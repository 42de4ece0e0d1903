#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cic/core/error.hpp"
#include "cic/tree/tree.hpp"
#include "support/random_trees.hpp"

using namespace cic;
using namespace cic::tree;

namespace {

// Expects parse(text) to fail with a message containing `column N` and `what`.
void expect_error(const std::string& text, int column, const std::string& what, const PrimitiveSet* ps = nullptr) {
    try {
        Tree::parse(text, ps);
        ADD_FAILURE() << "no error for '" << text << "'";
    } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("column " + std::to_string(column) + ":"), std::string::npos) << m;
        EXPECT_NE(m.find(what), std::string::npos) << m;
    }
}

} // namespace

TEST(SExpr, PrintsTheDocumentedForm) {
    const Tree t({Node::variable(0), Node::variable(1), Node::function(Op::Mul), Node::constant(1.5),
                  Node::function(Op::Add)});
    EXPECT_EQ(t.to_string(), "(add (mul x0 x1) 1.5)");
    EXPECT_EQ(Tree({Node::constant(0.1)}).to_string(), "0.10000000000000001");
    EXPECT_EQ(Tree({Node::variable(12)}).to_string(), "x12");
}

TEST(SExpr, ParsesHandEditedText) {
    const Tree t = Tree::parse("  ( add\n\t(mul x0   x1)\n 1.5 )  ");
    EXPECT_EQ(t.to_string(), "(add (mul x0 x1) 1.5)");
    EXPECT_EQ(Tree::parse("(sub x y)").to_string(), "(sub x0 x1)");   // aliases
    EXPECT_EQ(Tree::parse("(neg z)").to_string(), "(neg x2)");
    EXPECT_EQ(Tree::parse("+2.5").root().value, 2.5);
    EXPECT_EQ(Tree::parse("-1e-3").root().value, -1e-3);
    EXPECT_EQ(Tree::parse(".5").root().value, 0.5);
    EXPECT_EQ(Tree::parse("(gauss(sin x0))").to_string(), "(gauss (sin x0))");
}

TEST(SExpr, RoundTripsThousandsOfRandomTreesExactly) {
    Rng rng(42);
    for (int n = 0; n < 3000; ++n) {
        const Tree t = trees::random_tree(rng, 7, 5);
        const std::string text = t.to_string();
        const Tree back = Tree::parse(text);
        ASSERT_EQ(back, t) << text;
        ASSERT_EQ(back.to_string(), text);
        for (std::size_t i = 0; i < t.size(); ++i) {   // exact bits, including the sign of zero
            if (t.nodes()[i].op == Op::Const) {
                ASSERT_EQ(std::signbit(t.nodes()[i].value), std::signbit(back.nodes()[i].value));
            }
        }
    }
}

TEST(SExpr, MalformedTextNamesColumnAndProblem) {
    expect_error("", 1, "no text");
    expect_error("(add x0 x1", 1, "never closed");
    expect_error("(add x0 x1))", 12, "unbalanced");
    expect_error("(foo x0)", 2, "unknown function 'foo'");
    expect_error("(add x0)", 1, "takes 2 arguments, got 1");
    expect_error("(sin x0 x1)", 1, "takes 1 argument, got 2");
    expect_error("(add x0 1.5.2)", 9, "expected a number");
    expect_error("(add x0 abc)", 9, "expected a number");
    expect_error("(add x0 1e999)", 9, "expected a number");
    expect_error("(add x0 nan)", 9, "expected a number");
    expect_error("(add x0 -inf)", 9, "expected a number");
    expect_error("(add x0 xq)", 9, "expected a variable");
    expect_error("(add x0 +-1)", 9, "expected a number");
    expect_error("(add x0 --1)", 9, "expected a number");
    expect_error("(add x0 x-1)", 9, "expected a variable");
    expect_error("( x0)", 3, "unknown function 'x0'");
    expect_error("()", 2, "expected a function name");
    expect_error("x0 x1", 4, "after the tree");
    expect_error("(neg x0) (neg x1)", 10, "after the tree");
    const PrimitiveSet ps({{Op::Add, Op::Mul}, {}, 2, {}});
    expect_error("(add x0 x2)", 9, "out of range", &ps);
    expect_error("(sin x0)", 2, "not in the function set", &ps);
    EXPECT_NO_THROW(Tree::parse("(add x0 (mul x1 -2))", &ps));
}

TEST(SExpr, DeepTextDoesNotOverflowTheStack) {
    std::string text;
    for (int i = 0; i < 5000; ++i) text += "(neg ";
    text += "x0";
    for (int i = 0; i < 5000; ++i) text += ")";
    const Tree t = Tree::parse(text);
    EXPECT_EQ(t.depth(), 5001);
    EXPECT_EQ(t.to_string(), text);
    std::string deepest;   // 65535 levels: the most a tree may have
    for (int i = 1; i < 65535; ++i) deepest += "(neg ";
    deepest += "x0" + std::string(65534, ')');
    const Tree d = Tree::parse(deepest);
    EXPECT_EQ(d.depth(), 65535);
    EXPECT_EQ(d.to_string(), deepest);
    std::string too_deep;
    for (int i = 0; i < 70000; ++i) too_deep += "(neg ";
    EXPECT_THROW(Tree::parse(too_deep), InputError);
}
