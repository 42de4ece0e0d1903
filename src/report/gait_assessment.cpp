// Gait assessment of a replay (see gait_assessment.hpp).
#include "cic/report/gait_assessment.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <vector>

#include "cic/experiments/hypergp/oscillation.hpp"
#include "cic/sim/recording_sampler.hpp"

namespace cic::report {
GaitAssessment assess_gait(const ReplayItem& item, double shaking_above_hz) {
    if (!(shaking_above_hz > 0)) throw std::invalid_argument("assess_gait: the shaking bound must be > 0 Hz");
    if (item.trace.size() < 2) throw std::invalid_argument("assess_gait: the replay has fewer than 2 trace rows");
    const auto& frames = item.recording.frames;
    if (frames.empty() || item.centre_body < 0 || static_cast<std::size_t>(item.centre_body) >= frames.front().size())
        throw std::invalid_argument("assess_gait: the replay has no frames of its centre module");

    GaitAssessment a;
    a.fitness = item.replayed_fitness;
    a.raw_fitness = item.raw_fitness;
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
    const sim::Quat q0 = frames.front()[c].quat;
    const sim::Vec3 local_up = sim::rotate({q0[0], -q0[1], -q0[2], -q0[3]}, {0, 0, 1});   // the body axis up at the start
    a.final_up = sim::rotate(frames.back()[c].quat, local_up)[2];
    a.flipped = a.final_up < 0;
    a.shaking = a.dominant_hz > shaking_above_hz;
    a.distance = item.distance;
    a.elevation = item.elevation;
    a.foot_names = item.foot_names;
    a.duty_factors = item.duty_factors;
    const bool stepping = a.dominant_hz >= kSteppingAboveHz;
    a.verdict = a.flipped                      ? "flipped"
                : a.shaking                    ? "shaking"
                : stepping                     ? "walking"
                : a.elevation >= a.distance    ? "standing up"
                                               : "sliding";
    return a;
}

} // namespace cic::report
