// Gait assessment of a replay (see gait_assessment.hpp).
#include "cic/app/gait_assessment.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <vector>

#include "experiments/hypergp/oscillation.hpp"

namespace cic::app {
namespace {

using Vec3 = std::array<double, 3>;

// v rotated by the unit quaternion q = (w, x, y, z); conjugate = true rotates by q^-1.
Vec3 rotate(const std::array<double, 4>& q, const Vec3& v, bool conjugate) {
    const double w = q[0], s = conjugate ? -1.0 : 1.0;
    const Vec3 u{s * q[1], s * q[2], s * q[3]};
    const Vec3 t{2 * (u[1] * v[2] - u[2] * v[1]), 2 * (u[2] * v[0] - u[0] * v[2]), 2 * (u[0] * v[1] - u[1] * v[0])};
    return {v[0] + w * t[0] + (u[1] * t[2] - u[2] * t[1]), v[1] + w * t[1] + (u[2] * t[0] - u[0] * t[2]),
            v[2] + w * t[2] + (u[0] * t[1] - u[1] * t[0])};
}

} // namespace

GaitAssessment assess_gait(const ReplayItem& item, double shaking_above_hz) {
    if (!(shaking_above_hz > 0)) throw std::invalid_argument("assess_gait: the shaking bound must be > 0 Hz");
    if (item.trace.size() < 2) throw std::invalid_argument("assess_gait: the replay has fewer than 2 trace rows");
    const auto& frames = item.recording.frames;
    if (frames.empty() || item.centre_body < 0 || static_cast<std::size_t>(item.centre_body) >= frames.front().size())
        throw std::invalid_argument("assess_gait: the replay has no frames of its centre module");

    GaitAssessment a;
    a.fitness = item.replayed_fitness;
    const std::size_t joints = item.trace.front().desired.size();
    std::vector<double> commands;
    commands.reserve(item.trace.size() * joints);
    double height_sum = 0;
    a.min_height = std::numeric_limits<double>::infinity();
    for (const auto& row : item.trace) {
        commands.insert(commands.end(), row.desired.begin(), row.desired.end());
        height_sum += row.centre[2];
        a.min_height = std::min(a.min_height, row.centre[2]);
    }
    a.mean_height = height_sum / static_cast<double>(item.trace.size());
    const double dt = item.trace[1].t - item.trace[0].t;
    a.dominant_hz = joints == 0 ? 0.0 : hypergp::dominant_frequency(commands, joints, dt);

    const auto c = static_cast<std::size_t>(item.centre_body);
    const Vec3 local_up = rotate(frames.front()[c].quat, {0, 0, 1}, true);   // the body axis pointing up at the start
    a.final_up = rotate(frames.back()[c].quat, local_up, false)[2];
    a.flipped = a.final_up < 0;
    a.shaking = a.dominant_hz > shaking_above_hz;
    return a;
}

} // namespace cic::app
