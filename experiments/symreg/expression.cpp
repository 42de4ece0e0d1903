// Recursive-descent parser for target expressions (grammar in expression.hpp).
#include "cic/experiments/symreg/expression.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "cic/core/error.hpp"

namespace cic::symreg {
namespace {

using Code = Expression::Code;
using Instruction = Expression::Instruction;

constexpr int max_nesting = 200;  // guards the recursion against "((((..." inputs

struct FunctionName {
    std::string_view name;
    Code code;
};
constexpr FunctionName functions[] = {
    {"sin", Code::Sin},   {"cos", Code::Cos}, {"tan", Code::Tan},   {"tanh", Code::Tanh},
    {"exp", Code::Exp},   {"log", Code::Log}, {"sqrt", Code::Sqrt}, {"abs", Code::Abs},
    {"atan", Code::Atan},
};

class Parser {
public:
    explicit Parser(std::string_view text) : text_(text) {}

    std::vector<Instruction> run(int& variables) {
        skip_space();
        if (pos_ == text_.size()) fail("expected an expression but the text is empty");
        sum();
        skip_space();
        if (pos_ != text_.size())
            fail("expected an operator (+ - * / ^) or the end of the expression but found " +
                 found());
        variables = variables_;
        return std::move(program_);
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw InputError("expression \"" + std::string(text_) + "\": column " +
                         std::to_string(pos_ + 1) + ": " + what);
    }
    std::string found() const {
        if (pos_ >= text_.size()) return "the end of the expression";
        return "'" + std::string(1, text_[pos_]) + "'";
    }
    void skip_space() {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    }
    bool accept(std::string_view token) {
        skip_space();
        if (text_.substr(pos_, token.size()) != token) return false;
        pos_ += token.size();
        return true;
    }
    void emit(Code c) { program_.push_back({c}); }

    void sum() {
        product();
        for (;;) {
            if (accept("+")) { product(); emit(Code::Add); }
            else if (accept("-")) { product(); emit(Code::Sub); }
            else return;
        }
    }
    void product() {
        unary();
        for (;;) {
            skip_space();
            // "**" is power, handled in power(); here only a single '*'.
            if (text_.substr(pos_, 2) == "**") return;
            if (accept("*")) { unary(); emit(Code::Mul); }
            else if (accept("/")) { unary(); emit(Code::Div); }
            else return;
        }
    }
    void unary() {
        if (++depth_ > max_nesting) fail("expression nested too deeply");
        if (accept("-")) { unary(); emit(Code::Neg); }
        else if (accept("+")) { unary(); }
        else power();
        --depth_;
    }
    void power() {
        primary();
        if (accept("**") || accept("^")) { unary(); emit(Code::Pow); }
    }
    void primary() {
        skip_space();
        if (pos_ >= text_.size())
            fail("expected a number, a variable, a function or '(' but found the end of the expression");
        const char c = text_[pos_];
        if (c == '(') {
            ++pos_;
            sum();
            if (!accept(")")) fail("expected ')' but found " + found());
            return;
        }
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') return identifier();
        fail("expected a number, a variable, a function or '(' but found " + found());
    }
    void number() {
        const std::size_t start = pos_;
        double v = 0.0;
        const char* first = text_.data() + pos_;
        const char* last = text_.data() + text_.size();
        auto [end, ec] = std::from_chars(first, last, v, std::chars_format::general);
        if (ec == std::errc::result_out_of_range) fail("number out of range");
        if (ec != std::errc()) fail("expected a number but found " + found());
        pos_ += static_cast<std::size_t>(end - first);
        if (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_')) {
            pos_ = start;
            fail("malformed number (write 2*x, not 2x)");
        }
        program_.push_back({Code::Const, v, 0});
    }
    void identifier() {
        const std::size_t start = pos_;
        while (pos_ < text_.size() &&
               (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
            ++pos_;
        const std::string_view id = text_.substr(start, pos_ - start);
        for (const auto& f : functions) {
            if (f.name != id) continue;
            if (!accept("(")) fail("expected '(' after function " + std::string(id) + " but found " + found());
            sum();
            if (!accept(")")) fail("expected ')' but found " + found());
            emit(f.code);
            return;
        }
        if (id == "pi") { program_.push_back({Code::Const, std::numbers::pi, 0}); return; }
        int var = -1;
        if (id == "x") var = 0;
        else if (id == "y") var = 1;
        else if (id == "z") var = 2;
        else if (id.size() == 2 && id[0] == 'x' && std::isdigit(static_cast<unsigned char>(id[1])))
            var = id[1] - '0';
        if (var < 0) {
            pos_ = start;
            fail("unknown name '" + std::string(id) +
                 "' (variables: x y z x0..x9; functions: sin cos tan tanh exp log sqrt abs atan; constant: pi)");
        }
        variables_ = std::max(variables_, var + 1);
        program_.push_back({Code::Var, 0.0, var});
    }

    std::string_view text_;
    std::size_t pos_ = 0;
    int depth_ = 0;
    int variables_ = 1;
    std::vector<Instruction> program_;
};

int stack_need(const std::vector<Instruction>& program) {
    int depth = 0, most = 0;
    for (const auto& ins : program) {
        if (ins.code == Code::Const || ins.code == Code::Var) ++depth;
        else if (ins.code == Code::Add || ins.code == Code::Sub || ins.code == Code::Mul ||
                 ins.code == Code::Div || ins.code == Code::Pow) --depth;
        most = std::max(most, depth);
    }
    return most;
}

} // namespace

Expression Expression::parse(std::string_view text) {
    Expression e;
    e.text_ = std::string(text);
    e.program_ = Parser(text).run(e.variables_);
    e.max_stack_ = stack_need(e.program_);
    return e;
}

double Expression::evaluate(std::span<const double> x) const {
    if (x.size() < static_cast<std::size_t>(variables_))
        throw std::invalid_argument("Expression::evaluate: \"" + text_ + "\" needs " +
                                    std::to_string(variables_) + " variables, got " +
                                    std::to_string(x.size()));
    std::vector<double> stack;
    stack.reserve(static_cast<std::size_t>(max_stack_));
    auto pop = [&stack] { const double v = stack.back(); stack.pop_back(); return v; };
    for (const auto& ins : program_) {
        switch (ins.code) {
        case Code::Const: stack.push_back(ins.value); break;
        case Code::Var: stack.push_back(x[static_cast<std::size_t>(ins.var)]); break;
        case Code::Add: { const double b = pop(); stack.back() += b; break; }
        case Code::Sub: { const double b = pop(); stack.back() -= b; break; }
        case Code::Mul: { const double b = pop(); stack.back() *= b; break; }
        case Code::Div: { const double b = pop(); stack.back() /= b; break; }
        case Code::Pow: { const double b = pop(); stack.back() = std::pow(stack.back(), b); break; }
        case Code::Neg: stack.back() = -stack.back(); break;
        case Code::Sin: stack.back() = std::sin(stack.back()); break;
        case Code::Cos: stack.back() = std::cos(stack.back()); break;
        case Code::Tan: stack.back() = std::tan(stack.back()); break;
        case Code::Tanh: stack.back() = std::tanh(stack.back()); break;
        case Code::Exp: stack.back() = std::exp(stack.back()); break;
        case Code::Log: stack.back() = std::log(stack.back()); break;
        case Code::Sqrt: stack.back() = std::sqrt(stack.back()); break;
        case Code::Abs: stack.back() = std::fabs(stack.back()); break;
        case Code::Atan: stack.back() = std::atan(stack.back()); break;
        }
    }
    return stack.back();
}

} // namespace cic::symreg
