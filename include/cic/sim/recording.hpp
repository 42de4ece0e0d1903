#pragma once
// Read-only records of a simulation, for the viewer, POV-Ray export and traces.
// The simulator writes them; everything else only reads them.
#include <array>
#include <vector>

namespace cic::sim {

struct Pose {
    std::array<double, 3> pos{};
    std::array<double, 4> quat{1, 0, 0, 0};   // w, x, y, z (ODE order)
};

enum class PartKind { Chassis, Panel };

// One box geom: which body it rides on, its size and its pose relative to the body.
struct Part {
    int body = 0;
    int module = 0;
    PartKind kind = PartKind::Chassis;
    std::array<double, 3> size{};     // full side lengths
    Pose offset;                       // relative to the body frame
};

struct Recording {
    std::vector<Part> parts;
    int body_count = 0;
    double frame_dt = 0.04;                    // s between frames
    std::vector<double> times;                 // per frame
    std::vector<std::vector<Pose>> frames;     // frames[f][body]
};

// One row per control step.
struct TraceRow {
    double t = 0.0;
    std::vector<double> desired;   // commanded angles after clamping
    std::vector<double> actual;    // measured joint angles
    std::array<double, 3> centre{};
    // With EvalOptions::record_ground: for each branch end (evaluate.hpp's
    // branch_ends, the feet), 1 when it touched the ground in any physics step
    // of this control step.
    std::vector<unsigned char> feet_on_ground;
};

} // namespace cic::sim
