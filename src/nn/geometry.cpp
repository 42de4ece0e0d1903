#include "cic/nn/geometry.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace cic::nn {

namespace {
void check_points(const std::vector<Point>& pts, const char* what) {
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (!std::isfinite(pts[i].x) || !std::isfinite(pts[i].y))
            throw std::invalid_argument(std::string("nn::Geometry: ") + what + " neuron " +
                                        std::to_string(i) + " has a non-finite coordinate");
}
} // namespace

void Geometry::validate() const {
    if (joints.empty()) throw std::invalid_argument("nn::Geometry: no joints (the robot has no actuated module)");
    if (hidden.empty()) throw std::invalid_argument("nn::Geometry: no hidden neurons");
    check_points(joints, "joint");
    check_points(hidden, "hidden");
}

NeuronLayout make_neuron_layout(const Geometry& g, const NeuralConfig& cfg) {
    g.validate();
    NeuronLayout l;
    l.input = g.joints;
    l.hidden = g.hidden;
    l.output = g.joints;
    l.joint_count = g.joints.size();
    l.bias = cfg.bias_input;
    l.clock = cfg.clock_inputs;
    if (l.bias) l.input.push_back(kBiasPoint);
    if (l.clock) {
        l.input.push_back(kClockSinPoint);
        l.input.push_back(kClockCosPoint);
    }
    return l;
}

int cppf_variable_count(const NeuralConfig& cfg) { return cfg.extra_cppf_inputs ? 7 : 4; }

} // namespace cic::nn
