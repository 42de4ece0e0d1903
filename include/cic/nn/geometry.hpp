#pragma once
// Where the substrate's neurons sit (thesis 3.3): plain 2-D coordinates in
// [-1, 1], derived elsewhere from the robot (experiments/hypergp/substrate_geometry).
// This layer knows nothing about robots, ODE or XML.
#include <cstddef>
#include <vector>

#include "cic/nn/config.hpp"

namespace cic::nn {

struct Point {
    double x = 0.0;
    double y = 0.0;
    bool operator==(const Point&) const = default;
};

// The robot-derived part of the substrate.
struct Geometry {
    std::vector<Point> joints;   // one per actuated joint, in the controller's joint order:
                                 // the input neuron and the output neuron of joint j sit here
    std::vector<Point> hidden;   // one per distinct module position

    // Throws std::invalid_argument: no joints, no hidden neurons, or a non-finite coordinate.
    void validate() const;
};

// Layer indices given to the CPPF when extra_cppf_inputs is on.
inline constexpr double kInputLayer = -1.0;
inline constexpr double kHiddenLayer = 0.0;
inline constexpr double kOutputLayer = 1.0;

// Coordinates of the extra input neurons (bias, clock). They sit on a row
// outside the robot's [-1, 1] box so they never share a point with a module.
inline constexpr Point kBiasPoint{0.0, 1.5};
inline constexpr Point kClockSinPoint{-0.5, 1.5};
inline constexpr Point kClockCosPoint{0.5, 1.5};

// Every neuron of the substrate, layer by layer. Input order: one per joint
// (angle / (pi/2)), then bias (if on), then clock sin, clock cos (if on).
struct NeuronLayout {
    std::vector<Point> input;
    std::vector<Point> hidden;
    std::vector<Point> output;
    std::size_t joint_count = 0;
    bool bias = false;
    bool clock = false;
};

// Validates g, then appends the optional inputs the config asks for.
NeuronLayout make_neuron_layout(const Geometry& g, const NeuralConfig& cfg);

// Number of CPPF variables: 4 (x1 y1 x2 y2), or 7 with extra_cppf_inputs
// (x1 y1 x2 y2 layer_src layer_dst distance). In tree text they are x0..x6.
int cppf_variable_count(const NeuralConfig& cfg);

} // namespace cic::nn
