#pragma once
// Checks of a tree's invariants, shared by the tree and gp tests.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "cic/tree/tree.hpp"

namespace cic::testing {

// Sizes and depths recounted with a plain stack, ignoring the cached fields.
inline ::testing::AssertionResult caches_correct(const tree::Tree& t) {
    struct SD { std::uint32_t size; int depth; };
    std::vector<SD> stack;
    const auto nodes = t.nodes();
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        SD me{1, 1};
        for (int k = 0; k < tree::arity(nodes[i].op); ++k) {
            if (stack.empty()) return ::testing::AssertionFailure() << "malformed at " << i;
            me.size += stack.back().size;
            me.depth = std::max(me.depth, stack.back().depth + 1);
            stack.pop_back();
        }
        if (nodes[i].size != me.size || nodes[i].depth != me.depth)
            return ::testing::AssertionFailure() << "wrong cache at node " << i << " of " << t.to_string();
        stack.push_back(me);
    }
    if (stack.size() != 1) return ::testing::AssertionFailure() << "not one tree";
    if (t.size() != nodes.size() || t.depth() != stack[0].depth) return ::testing::AssertionFailure() << "root";
    return ::testing::AssertionSuccess();
}

} // namespace cic::testing
