// CSV reading for symbolic-regression data files.
#include "cic/experiments/symreg/dataset.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <string_view>

#include "cic/core/error.hpp"

namespace cic::symreg {
namespace {

std::string_view trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    const auto last = s.find_last_not_of(" \t\r");
    return s.substr(first, last - first + 1);
}

std::vector<std::string_view> split(std::string_view line) {
    std::vector<std::string_view> fields;
    for (;;) {
        const auto comma = line.find(',');
        fields.push_back(trim(line.substr(0, comma)));
        if (comma == std::string_view::npos) return fields;
        line.remove_prefix(comma + 1);
    }
}

bool skipped(std::string_view line) {
    const auto t = trim(line);
    return t.empty() || t.front() == '#';
}

} // namespace

Dataset load_csv(const std::filesystem::path& file) {
    const std::string name = file.string();
    std::ifstream in(file);
    if (!in) throw InputError("cannot open the data file", name);

    Dataset d;
    std::string line;
    int line_no = 0;
    std::size_t width = 0;
    while (std::getline(in, line)) {
        ++line_no;
        if (skipped(line)) continue;
        const auto fields = split(line);
        if (width == 0) {   // the header
            if (fields.size() < 2)
                throw InputError("the header needs at least two columns (variables, then the target), found " +
                                     std::to_string(fields.size()),
                                 name, line_no);
            width = fields.size();
            for (std::size_t i = 0; i + 1 < width; ++i) {
                if (fields[i].empty())
                    throw InputError("column " + std::to_string(i + 1) + " of the header has no name", name, line_no);
                d.variable_names.emplace_back(fields[i]);
            }
            d.columns.resize(width - 1);
            continue;
        }
        if (fields.size() != width)
            throw InputError("expected " + std::to_string(width) + " columns as in the header, found " +
                                 std::to_string(fields.size()),
                             name, line_no);
        for (std::size_t i = 0; i < width; ++i) {
            const auto f = fields[i];
            double v = 0.0;
            const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
            if (f.empty() || ec != std::errc() || end != f.data() + f.size() || !std::isfinite(v)) {
                const std::string column = i + 1 < width ? d.variable_names[i] : "target";
                throw InputError("column " + std::to_string(i + 1) + " (" + column + "): '" + std::string(f) +
                                     "' is not a finite number",
                                 name, line_no);
            }
            if (i + 1 < width) d.columns[i].push_back(v);
            else d.target.push_back(v);
        }
    }
    if (width == 0) throw InputError("the data file is empty (expected a header line)", name, line_no);
    if (d.target.empty()) throw InputError("the data file has a header but no data rows", name, line_no);
    d.description = name + ": " + std::to_string(d.rows()) + " rows, " + std::to_string(d.variables()) +
                    " variables";
    return d;
}

} // namespace cic::symreg
