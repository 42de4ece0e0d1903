#pragma once
// Batch evaluation of trees: one postfix sweep over blocks of rows, so the
// cost per node is amortised over many inputs (symreg samples, substrate pairs).
#include <cstddef>
#include <span>

#include "cic/tree/tree.hpp"

namespace cic::tree {

// Evaluates `t` on `rows` rows. columns[v] points at `rows` values of variable v
// (column-major). Writes `rows` results to out. Thread-safe (no shared state).
// Throws std::invalid_argument if a variable index >= columns.size() or out is short.
void evaluate(const Tree& t, std::span<const double* const> columns, std::size_t rows,
              std::span<double> out);

// Convenience for one point.
double evaluate_point(const Tree& t, std::span<const double> x);

} // namespace cic::tree
