// Checks of a SimConfig against its one field description (config.hpp).
#include "cic/sim/config.hpp"

#include <charconv>
#include <cmath>
#include <string>

namespace cic::sim {

namespace {

// Shortest text that reads back as v ("0.025", not "0.025000000000000001"),
// as the settings writer formats numbers.
std::string number(double v) {
    char buf[64];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, end) : std::to_string(v);
}

std::string range_text(const FieldSpec& f) {
    constexpr double kHuge = std::numeric_limits<double>::max();
    std::string lo = f.min == -kHuge ? "" : (f.min_exclusive ? "> " : ">= ") + number(f.min);
    std::string hi = f.max == kHuge ? "" : "<= " + number(f.max);
    std::string text = lo.empty() ? hi : hi.empty() ? lo : lo + " and " + hi;
    if (!f.allow_inf) text = text.empty() ? "finite" : "finite and " + text;
    return text;
}

template <class T>
bool in_range(const FieldSpec& f, T v) {
    if constexpr (std::is_same_v<T, bool>) {
        return true;
    } else {
        const double d = static_cast<double>(v);
        if (std::isnan(d)) return false;
        if (std::isinf(d)) return f.allow_inf;
        return (f.min_exclusive ? d > f.min : d >= f.min) && d <= f.max;
    }
}

} // namespace

std::vector<ConfigProblem> config_problems(const SimConfig& c) {
    std::vector<ConfigProblem> out;
    for_each_field(c, [&](const FieldSpec& f, const auto& v) {
        if (!in_range(f, v)) out.push_back({{f.name}, std::string(f.name) + " must be " + range_text(f)});
    });
    if (!out.empty()) return out;   // the rules below assume every field in range

    if (!(c.sample_from < c.sample_to))
        out.push_back({{"sample_from", "sample_to"}, "the simulation must start before it stops"});
    if (!(c.sample_from <= c.delayed_start && c.delayed_start < c.sample_to))
        out.push_back({{"delayed_start", "sample_from", "sample_to"},
                       "delayed_start must lie in [sample_from, sample_to)"});
    if (c.sample_step > c.sample_to - c.sample_from)
        out.push_back({{"sample_step", "sample_from", "sample_to"}, "the control step is longer than the simulated time"});
    else if ((c.sample_to - c.sample_from) / c.sample_step > 1e9)
        out.push_back({{"sample_step", "sample_from", "sample_to"}, "more than 10^9 control steps"});
    if (!c.allow_coarse_step && c.physics_step() > kMaxStablePhysicsStep)
        out.push_back({{"sample_step", "step_divider"},
                       "the physics step sample_step / extraTimeStepDivider = " + number(c.physics_step()) +
                           " s is above the stability bound " + number(kMaxStablePhysicsStep) +
                           " s (docs/simulator.md); raise extraTimeStepDivider, or set Simulator.allowCoarseStep = 1 "
                           "to accept physics artefacts"});
    return out;
}

} // namespace cic::sim
