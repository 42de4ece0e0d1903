// A fitness that sees the whole walk, built outside cic (docs/extending.md,
// "A fitness from the whole walk"): `circle`, HyperGP controllers scored by how
// far the robot turns around the middle of its own path (radians swept), times
// how round that path is, with <CircleWalk> minRadius (m) below which a robot
// that stays put scores 0. It asks the simulator for the centre's path
// (WalkNeeds::trace), so only its runs pay for recording it; `view`, `assess`,
// `trace` and Python's cic.simulate replay this score, eq. 7.1 beside it.
#include <cmath>
#include <numbers>
#include <vector>

#include "cic/experiments/registry.hpp"
#include "cic/io/settings_extension.hpp"

namespace {

using namespace cic;

double circling(const hypergp::Model&, const io::Settings& settings, const hypergp::Outcome& o) {
    const std::vector<sim::TraceRow>& path = o.result.trace;   // one row per control step
    if (path.size() < 2) return 0.0;
    double mx = 0, my = 0;
    for (const auto& row : path) {
        mx += row.centre[0];
        my += row.centre[1];
    }
    mx /= static_cast<double>(path.size());
    my /= static_cast<double>(path.size());
    double swept = 0, mean_r = 0, mean_r2 = 0;
    double last = std::atan2(path.front().centre[1] - my, path.front().centre[0] - mx);
    for (const auto& row : path) {
        const double dx = row.centre[0] - mx, dy = row.centre[1] - my;
        const double angle = std::atan2(dy, dx);
        double step = angle - last;   // unwrapped: the shorter way round
        if (step > std::numbers::pi) step -= 2 * std::numbers::pi;
        if (step < -std::numbers::pi) step += 2 * std::numbers::pi;
        swept += step;
        last = angle;
        const double r = std::hypot(dx, dy);
        mean_r += r;
        mean_r2 += r * r;
    }
    const double n = static_cast<double>(path.size());
    mean_r /= n;
    if (mean_r < io::extra_number(settings, "CircleWalk", "minRadius")) return 0.0;   // standing still
    const double sd = std::sqrt(std::max(0.0, mean_r2 / n - mean_r * mean_r));
    return std::fabs(swept) / (1.0 + sd / mean_r);
}

const experiments::Registrar registrar{{
    .type = {"circle", io::ExperimentFamily::HyperGP, "CircleWalk",
             "HyperGP scored by the radians the robot turns around the middle of its path, times its roundness"},
    .keys = {io::extra_number_key("CircleWalk", "minRadius", 0.02, 0.0, 10.0,
                                  "Mean distance (m) from the path's middle below which the robot counts as standing")},
    .check_inputs = &hypergp::check_inputs,
    .score = &circling,
    .needs = {.trace = true},
}};

} // namespace
