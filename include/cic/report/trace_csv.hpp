#pragma once
// Network traces as CSV: per control step the raw controller outputs, the
// averaged commands the joints received, the measured joint angles and the
// centre position (the data behind thesis figures 7.8-7.10).
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "cic/sim/recording.hpp"

namespace cic::report {

struct TraceSample {
    double t = 0.0;
    std::vector<double> outputs;    // raw controller (network) outputs, one per joint
    std::vector<double> commands;   // commands after averaging and clamping
    std::vector<double> angles;     // measured joint angles
    std::array<double, 3> centre{};
};

struct TraceTable {
    std::vector<std::string> joints;
    std::vector<TraceSample> rows;
};

// Joins the simulator's rows with the raw outputs recorded per control step
// (raw_outputs[i] belongs to rows[i]). Throws std::invalid_argument when the
// counts differ.
std::vector<TraceSample> make_trace(const std::vector<sim::TraceRow>& rows,
                                    const std::vector<std::vector<double>>& raw_outputs);

// Columns: t, out_<j>..., cmd_<j>..., angle_<j>..., cx, cy, cz. Joint names may
// hold letters, digits, '.', '_', '+' and '-' only. Throws std::invalid_argument for
// bad names or rows of the wrong width, cic::InputError when the file cannot be written.
void write_trace_csv(const std::filesystem::path& path, const std::vector<TraceSample>& rows,
                     const std::vector<std::string>& joint_names);

// Reads a file written by write_trace_csv. Throws cic::InputError naming the
// file and line for anything else.
TraceTable read_trace_csv(const std::filesystem::path& path);

} // namespace cic::report
