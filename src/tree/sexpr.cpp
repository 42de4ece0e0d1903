// The S-expression text form of trees: "(add (mul x0 x1) 1.5)".
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cic/core/error.hpp"
#include "cic/tree/tree.hpp"

namespace cic::tree {

namespace {

void append_constant(std::string& out, double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    out += buf;
}

// Prefix walk with an explicit stack (trees may be 65535 levels deep).
void write(const Tree& t, std::string& out) {
    struct Frame {
        std::size_t child[2];
        int arity;
        int next;
    };
    const auto nodes = t.nodes();
    std::vector<Frame> stack;
    auto visit = [&](std::size_t i) {
        const Node& n = nodes[i];
        if (n.op == Op::Const) return append_constant(out, n.value);
        if (n.op == Op::Var) {
            out += 'x';
            out += std::to_string(n.var);
            return;
        }
        out += '(';
        out += name(n.op);
        Frame f{{0, 0}, arity(n.op), 0};
        if (f.arity == 1) f.child[0] = i - 1;
        else { f.child[1] = i - 1; f.child[0] = i - 1 - nodes[i - 1].size; }
        stack.push_back(f);
    };
    visit(nodes.size() - 1);
    while (!stack.empty()) {
        Frame& f = stack.back();
        if (f.next == f.arity) {
            out += ')';
            stack.pop_back();
            continue;
        }
        out += ' ';
        visit(f.child[f.next++]);   // may grow the stack: f is not used afterwards
    }
}

bool is_delimiter(char c) { return c == '(' || c == ')' || std::isspace(static_cast<unsigned char>(c)); }

// Parses the postfix form directly with an explicit stack, so deep text cannot
// overflow the call stack.
class Parser {
public:
    Parser(std::string_view text, const PrimitiveSet* ps) : text_(text), ps_(ps) {}

    Tree run() {
        skip_space();
        while (pos_ < text_.size()) {
            const char c = text_[pos_];
            if (c == '(') {
                open();
            } else if (c == ')') {
                close();
            } else {
                const std::size_t col = pos_;
                nodes_.push_back(terminal(token()));
                finished_subtree(col);
            }
            skip_space();
        }
        if (!frames_.empty()) fail(frames_.back().column, "'(' is never closed");
        if (nodes_.empty()) fail(pos_, "expected a tree, found no text");
        return Tree(std::move(nodes_));
    }

private:
    struct Frame {
        Op op;
        int args;
        std::size_t column;
    };

    [[noreturn]] void fail(std::size_t at, const std::string& what) const {
        std::string shown(text_.substr(0, 80));
        if (text_.size() > 80) shown += "...";
        throw InputError("tree text, column " + std::to_string(at + 1) + ": " + what + " in '" + shown + "'");
    }

    void skip_space() {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    }

    std::string_view token() {
        const std::size_t b = pos_;
        while (pos_ < text_.size() && !is_delimiter(text_[pos_])) ++pos_;
        return text_.substr(b, pos_ - b);
    }

    void open() {
        const std::size_t col = pos_;
        if (root_done_) fail(col, "unexpected text after the tree");
        ++pos_;
        skip_space();
        const std::size_t name_col = pos_;
        const std::string_view n = token();
        if (n.empty()) fail(name_col, "expected a function name after '('");
        const auto op = function_from_name(n);
        if (!op) fail(name_col, "unknown function '" + std::string(n) + "'");
        if (ps_ && !ps_->allows(*op)) fail(name_col, "function '" + std::string(n) + "' is not in the function set");
        if (frames_.size() >= 65534) fail(col, "tree deeper than 65535 levels");
        frames_.push_back({*op, 0, col});
    }

    void close() {
        if (frames_.empty()) fail(pos_, "unbalanced ')'");
        const Frame f = frames_.back();
        if (f.args != arity(f.op))
            fail(f.column, "'" + std::string(name(f.op)) + "' takes " + std::to_string(arity(f.op)) +
                               " argument" + (arity(f.op) == 1 ? "" : "s") + ", got " + std::to_string(f.args));
        frames_.pop_back();
        ++pos_;
        nodes_.push_back(Node::function(f.op));
        finished_subtree(f.column);
    }

    void finished_subtree(std::size_t col) {
        if (frames_.empty()) {
            if (root_done_) fail(col, "unexpected text after the tree");
            root_done_ = true;
        } else {
            ++frames_.back().args;
        }
    }

    Node terminal(std::string_view tok) {
        const std::size_t col = pos_ - tok.size();
        if (tok[0] == 'x' || tok[0] == 'y' || tok[0] == 'z') return variable(tok, col);
        double v = 0.0;
        const char* end = tok.data() + tok.size();
        const char* first = tok.data() + (tok[0] == '+' ? 1 : 0);   // from_chars rejects a leading '+'
        const auto [p, ec] = std::from_chars(first, end, v);
        if (ec != std::errc() || p != end || !std::isfinite(v) ||
            !(std::isdigit(static_cast<unsigned char>(*first)) || *first == '.' || (*first == '-' && first == tok.data())))
            fail(col, "expected a number or a variable x0, x1, ..., got '" + std::string(tok) + "'");
        return Node::constant(v);
    }

    Node variable(std::string_view tok, std::size_t col) {
        int index = 0;
        if (tok.size() == 1) {
            index = tok[0] == 'x' ? 0 : tok[0] == 'y' ? 1 : 2;   // aliases x, y, z = x0, x1, x2
        } else {
            const char* end = tok.data() + tok.size();
            const auto [p, ec] = std::from_chars(tok.data() + 1, end, index);
            if (tok[0] != 'x' || ec != std::errc() || p != end || index < 0 || index > 65535 ||
                !std::isdigit(static_cast<unsigned char>(tok[1])))
                fail(col, "expected a variable x0, x1, ... or a number, got '" + std::string(tok) + "'");
        }
        if (ps_ && index >= ps_->variable_count())
            fail(col, "variable '" + std::string(tok) + "' is out of range (" +
                          std::to_string(ps_->variable_count()) + " variables)");
        return Node::variable(index);
    }

    std::string_view text_;
    const PrimitiveSet* ps_;
    std::size_t pos_ = 0;
    std::vector<Frame> frames_;
    std::vector<Node> nodes_;
    bool root_done_ = false;
};

} // namespace

std::string Tree::to_string() const {
    if (nodes_.empty()) return {};
    std::string out;
    out.reserve(nodes_.size() * 6);
    write(*this, out);
    return out;
}

Tree Tree::parse(std::string_view text, const PrimitiveSet* ps) { return Parser(text, ps).run(); }

} // namespace cic::tree
