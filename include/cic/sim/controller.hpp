#pragma once
// What drives a robot: each control step it sees the joint angles and the
// time and returns desired angles (clamped to +-pi/2 by the simulator).
#include <span>
#include <vector>

namespace cic::sim {

class Controller {
public:
    virtual ~Controller() = default;
    // Called once before the first step with the number of actuated joints.
    virtual void reset(std::size_t joints) = 0;
    // angles.size() == desired.size() == joints.
    virtual void step(double t, std::span<const double> angles, std::span<double> desired) = 0;
};

class ConstantController final : public Controller {
public:
    explicit ConstantController(double angle = 0.0) : angle_(angle) {}
    void reset(std::size_t) override {}
    void step(double, std::span<const double>, std::span<double> desired) override;
private:
    double angle_;
};

struct SineJoint {
    double amplitude = 0.5;  // rad
    double frequency = 0.5;  // Hz
    double phase = 0.0;      // rad
};

// desired_j(t) = A_j sin(2 pi f_j t + phi_j). Joints beyond params.size() reuse the last entry.
class SineController final : public Controller {
public:
    explicit SineController(std::vector<SineJoint> params);
    void reset(std::size_t joints) override;
    void step(double t, std::span<const double>, std::span<double> desired) override;
private:
    std::vector<SineJoint> params_;
};

// An open-loop parameterised gait (the `gait` experiment's controller, a
// baseline for evolved networks): one shared frequency f, and per joint
//   desired_j(t) = offset_j + a_j sin(2 pi f t + phi_j) + b_j sin(4 pi f t + psi_j),
// the second harmonic (b, psi) being optional (b = 0). The simulator clamps the
// result to the servo's range.
struct GaitJoint {
    double amplitude = 0.0;    // a, rad
    double phase = 0.0;        // phi, rad
    double offset = 0.0;       // rad
    double amplitude2 = 0.0;   // b, rad (second harmonic)
    double phase2 = 0.0;       // psi, rad
};

struct GaitSpec {
    double frequency = 0.5;    // Hz, shared by every joint
    std::vector<GaitJoint> joints;
};

// Joints beyond spec.joints.size() hold 0. Throws std::invalid_argument for an
// empty spec, a negative or non-finite frequency or a non-finite parameter.
class GaitController final : public Controller {
public:
    explicit GaitController(GaitSpec spec);
    void reset(std::size_t) override {}
    void step(double t, std::span<const double>, std::span<double> desired) override;
private:
    GaitSpec spec_;
};

// A tripod gait for the legged presets: `legs` legs of `joints_per_leg` joints each,
// in preset order (legs in pairs along the torso, sides +x then -x). The first joint
// of a leg lifts it; its other joints lag by a quarter period; neighbouring legs are
// half a period apart. tripod_gait(6, 3) walks R1 with 6 legs forward (a small grid
// search found it; the simulator tests and benchmarks use it). Throws
// std::invalid_argument for legs < 1 or joints_per_leg < 1.
std::vector<SineJoint> tripod_gait(int legs, int joints_per_leg, double amplitude = 1.0, double frequency = 0.5);

} // namespace cic::sim
