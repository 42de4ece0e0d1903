// Unit box <-> gait parameters (see encoding.hpp).
#include "cic/experiments/gait/encoding.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace cic::gait {

Encoding::Encoding(std::size_t joints_, bool second_harmonic_, double frequency_min_, double frequency_max_,
                   Bounds bounds_)
    : joints(joints_), second_harmonic(second_harmonic_), frequency_min(frequency_min_), frequency_max(frequency_max_),
      bounds(bounds_) {
    if (joints == 0) throw std::invalid_argument("gait encoding: the robot has no joints");
    if (!(frequency_min > 0) || !(frequency_max >= frequency_min) || !std::isfinite(frequency_max))
        throw std::invalid_argument("gait encoding: need 0 < frequency_min <= frequency_max");
}

sim::GaitSpec Encoding::decode(std::span<const double> x) const {
    if (x.size() != dimension())
        throw std::invalid_argument("gait encoding: " + std::to_string(x.size()) + " parameters, expected " +
                                    std::to_string(dimension()));
    for (double v : x)
        if (!std::isfinite(v)) throw std::invalid_argument("gait encoding: a parameter is not finite");
    constexpr double pi = std::numbers::pi;
    auto unit = [this](double v) { return to_unit(v, bounds); };
    auto angle = [&](double v) { return 2.0 * pi * (v - std::floor(v)); };
    sim::GaitSpec g;
    g.frequency = frequency_min + unit(x[0]) * (frequency_max - frequency_min);
    g.joints.resize(joints);
    for (std::size_t j = 0; j < joints; ++j) {
        const double* p = x.data() + 1 + j * per_joint();
        sim::GaitJoint& out = g.joints[j];
        out.amplitude = unit(p[0]) * pi / 2;
        out.phase = angle(p[1]);
        out.offset = (2.0 * unit(p[2]) - 1.0) * pi / 2;
        if (second_harmonic) {
            out.amplitude2 = unit(p[3]) * pi / 2;
            out.phase2 = angle(p[4]);
        }
    }
    return g;
}

std::vector<double> Encoding::in_box(std::span<const double> x) const {
    (void)decode(x);   // the same checks
    std::vector<double> out(x.begin(), x.end());
    out[0] = to_unit(x[0], bounds);
    for (std::size_t j = 0; j < joints; ++j) {
        double* p = out.data() + 1 + j * per_joint();
        p[0] = to_unit(p[0], bounds);
        p[1] = p[1] - std::floor(p[1]);   // decode's angle(): 2 pi (v - floor v), the same bits from [0, 1)
        p[2] = to_unit(p[2], bounds);
        if (second_harmonic) {
            p[3] = to_unit(p[3], bounds);
            p[4] = p[4] - std::floor(p[4]);
        }
    }
    return out;
}

double to_unit(double v, Bounds bounds) {
    if (bounds == Bounds::Clamp) return std::clamp(v, 0.0, 1.0);
    const double t = v - 2.0 * std::floor(v / 2.0);   // in [0, 2): the triangle wave's period
    return t <= 1.0 ? t : 2.0 - t;
}

int default_population(std::size_t dimension, int at_least) {
    const int hansen = 4 + static_cast<int>(std::floor(3.0 * std::log(static_cast<double>(std::max<std::size_t>(1, dimension)))));
    return std::max(hansen, at_least);
}

} // namespace cic::gait
