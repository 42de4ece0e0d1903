#pragma once
// Training data of a symbolic-regression run, and reading it from CSV.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace cic::symreg {

struct Dataset {
    std::vector<std::string> variable_names;   // x0, x1, ... or the CSV header
    std::vector<std::vector<double>> columns;  // columns[v][row]
    std::vector<double> target;                // target[row]
    std::string description;                   // one line, for logs and run summaries

    std::size_t rows() const { return target.size(); }
    int variables() const { return static_cast<int>(columns.size()); }
};

// CSV: a header line of names, then one row of numbers per line; the last
// column is the target, the others are the variables x0, x1, ... in order.
// Separator ',' ; spaces around fields are ignored; blank lines and lines
// starting with '#' are skipped; no quoting. At least one variable and one row.
// Errors name file:line (cic::InputError): missing file, wrong column count,
// a field that is not a finite number (with the column's name).
Dataset load_csv(const std::filesystem::path& file);

} // namespace cic::symreg
