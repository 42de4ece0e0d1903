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

} // namespace cic::sim
