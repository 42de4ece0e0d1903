#pragma once
// Infix expressions for symbolic-regression targets: "x^4 + x^3 + x^2 + x",
// "sin(x) + sin(y^2)", "2*sin(x0)*cos(x1)". Parsed once into a postfix
// program, then evaluated point by point (targets are sampled once per run,
// so speed does not matter here; GP trees use tree::evaluate instead).
//
// Grammar (precedence low to high):
//   sum     := product (('+' | '-') product)*
//   product := unary (('*' | '/') unary)*
//   unary   := ('-' | '+') unary | power
//   power   := primary (('^' | '**') unary)?       right-associative
//   primary := number | 'pi' | variable | function '(' sum ')' | '(' sum ')'
// As in mathematics, unary minus binds looser than '^': -2^2 = -(2^2) = -4,
// and 2^-1 = 0.5. Variables: x (= x0), y (= x1), z (= x2), x0 .. x9.
// Functions: sin cos tan tanh exp log sqrt abs atan (plain, unprotected maths).
// Numbers: 3, 0.5, .5, 1e-3, 2.5E+2.
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace cic::symreg {

class Expression {
public:
    // Throws cic::InputError naming the 1-based column and what was expected.
    static Expression parse(std::string_view text);

    // x[i] is variable xi; x must hold at least variables() values
    // (std::invalid_argument otherwise).
    double evaluate(std::span<const double> x) const;

    // 1 + the highest variable index used; at least 1 (a constant is f(x)).
    int variables() const { return variables_; }
    const std::string& text() const { return text_; }

    // One instruction of the postfix program (public for the parser only).
    enum class Code : unsigned char {
        Const, Var, Add, Sub, Mul, Div, Pow, Neg,
        Sin, Cos, Tan, Tanh, Exp, Log, Sqrt, Abs, Atan
    };
    struct Instruction {
        Code code;
        double value = 0.0;  // Const
        int var = 0;         // Var
    };

private:
    std::string text_;
    std::vector<Instruction> program_;
    int variables_ = 1;
    int max_stack_ = 0;
};

} // namespace cic::symreg
