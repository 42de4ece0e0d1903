#include "cic/report/trace_csv.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <fstream>
#include <stdexcept>

#include "cic/core/error.hpp"

namespace cic::report {
namespace {

bool valid_name(const std::string& s) {
    if (s.empty()) return false;
    for (char c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-' || c == '+')) return false;
    return true;
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = line.find(',', start);
        out.push_back(line.substr(start, comma - start));
        if (comma == std::string::npos) return out;
        start = comma + 1;
    }
}

} // namespace

std::vector<TraceSample> make_trace(const std::vector<sim::TraceRow>& rows,
                                    const std::vector<std::vector<double>>& raw_outputs) {
    if (raw_outputs.size() != rows.size())
        throw std::invalid_argument(fmt::format("make_trace: {} trace rows but {} raw output rows", rows.size(),
                                                raw_outputs.size()));
    std::vector<TraceSample> out;
    out.reserve(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i)
        out.push_back({rows[i].t, raw_outputs[i], rows[i].desired, rows[i].actual, rows[i].centre});
    return out;
}

void write_trace_csv(const std::filesystem::path& path, const std::vector<TraceSample>& rows,
                     const std::vector<std::string>& joint_names) {
    for (const auto& name : joint_names)
        if (!valid_name(name)) throw std::invalid_argument("write_trace_csv: bad joint name '" + name + "'");
    const std::size_t n = joint_names.size();
    std::string text = "t";
    for (const char* prefix : {"out_", "cmd_", "angle_"})
        for (const auto& name : joint_names) text += "," + std::string(prefix) + name;
    text += ",cx,cy,cz\n";
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const TraceSample& s = rows[r];
        if (s.outputs.size() != n || s.commands.size() != n || s.angles.size() != n)
            throw std::invalid_argument(fmt::format("write_trace_csv: row {} does not have {} values per column group",
                                                    r, n));
        text += fmt::format("{:.6g}", s.t);
        for (const auto* v : {&s.outputs, &s.commands, &s.angles})
            for (double x : *v) text += fmt::format(",{:.9g}", x);
        text += fmt::format(",{:.9g},{:.9g},{:.9g}\n", s.centre[0], s.centre[1], s.centre[2]);
    }
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw InputError("cannot write trace file", path.string());
}

TraceTable read_trace_csv(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw InputError("cannot read trace file", path.string());
    const std::string file = path.string();
    std::string line;
    if (!std::getline(in, line)) throw InputError("empty trace file (expected a header line)", file, 1);
    const auto header = split(line);
    // t + 3 groups of n + cx,cy,cz
    if (header.size() < 4 || (header.size() - 4) % 3 != 0 || header.front() != "t" ||
        header[header.size() - 3] != "cx" || header[header.size() - 2] != "cy" || header.back() != "cz")
        throw InputError("not a trace header (expected t,out_<joint>...,cmd_<joint>...,angle_<joint>...,cx,cy,cz)",
                         file, 1);
    const std::size_t n = (header.size() - 4) / 3;
    TraceTable table;
    for (std::size_t j = 0; j < n; ++j) {
        const std::string& h = header[1 + j];
        if (!h.starts_with("out_") || header[1 + n + j] != "cmd_" + h.substr(4) ||
            header[1 + 2 * n + j] != "angle_" + h.substr(4))
            throw InputError(fmt::format("column {} ('{}') does not match the out_/cmd_/angle_ pattern", 2 + j, h),
                             file, 1);
        table.joints.push_back(h.substr(4));
    }
    int line_no = 1;
    while (std::getline(in, line)) {
        ++line_no;
        if (line.empty()) continue;
        const auto cells = split(line);
        if (cells.size() != header.size())
            throw InputError(fmt::format("{} values, expected {}", cells.size(), header.size()), file, line_no);
        std::vector<double> v(cells.size());
        for (std::size_t c = 0; c < cells.size(); ++c) {
            const auto& cell = cells[c];
            const auto res = std::from_chars(cell.data(), cell.data() + cell.size(), v[c]);
            if (res.ec != std::errc() || res.ptr != cell.data() + cell.size())
                throw InputError(fmt::format("column '{}': '{}' is not a number", header[c], cell), file, line_no);
        }
        TraceSample s;
        s.t = v[0];
        s.outputs.assign(v.begin() + 1, v.begin() + 1 + static_cast<long>(n));
        s.commands.assign(v.begin() + 1 + static_cast<long>(n), v.begin() + 1 + 2 * static_cast<long>(n));
        s.angles.assign(v.begin() + 1 + 2 * static_cast<long>(n), v.begin() + 1 + 3 * static_cast<long>(n));
        s.centre = {v[v.size() - 3], v[v.size() - 2], v[v.size() - 1]};
        table.rows.push_back(std::move(s));
    }
    return table;
}

} // namespace cic::report
