#pragma once
// The gait experiment's genotype: a point of the unit box [0, 1]^n that the
// optimiser searches, decoded into a sim::GaitSpec. Working in the unit box
// gives every parameter the same scale, so one initial step (Gait.sigma0)
// suits them all. Layout: x[0] is the shared frequency, then per joint
// amplitude, phase, offset [, amplitude2, phase2].
//   frequency   f_min + x (f_max - f_min)
//   amplitudes  x * pi/2                 (the servo's half range)
//   offset      (2x - 1) * pi/2          (the servo's range)
//   phases      x * 2 pi                 (periodic: any x is meaningful)
// CMA-ES and xNES sample the whole space, so a value outside [0, 1] must be
// read somehow (the phases simply wrap by periodicity); the others follow
// Bounds: Clamp reads the nearest bound, which leaves the fitness flat outside
// the box, so the optimiser's mean can drift out along it unchecked; Reflect
// mirrors at the bounds (a triangle wave: 1.2 -> 0.8, -0.3 -> 0.3), keeping
// the landscape continuous, the usual remedy (pycma's BoundTransform and
// libcmaes' pwqBoundStrategy are smoothed versions of it).
#include <cstddef>
#include <span>
#include <vector>

#include "cic/sim/controller.hpp"

namespace cic::gait {

enum class Bounds { Clamp, Reflect };

struct Encoding {
    std::size_t joints = 0;
    bool second_harmonic = false;
    double frequency_min = 0.1;
    double frequency_max = 3.0;
    Bounds bounds = Bounds::Clamp;

    // Throws std::invalid_argument for no joints or a bad frequency range.
    Encoding(std::size_t joints, bool second_harmonic, double frequency_min, double frequency_max,
             Bounds bounds = Bounds::Clamp);

    std::size_t per_joint() const { return second_harmonic ? 5 : 3; }
    std::size_t dimension() const { return 1 + joints * per_joint(); }
    // Throws std::invalid_argument when x.size() != dimension() or x holds a non-finite value.
    sim::GaitSpec decode(std::span<const double> x) const;
    // The point of the unit box that decodes to the same gait, bit for bit:
    // each parameter read as decode reads it (Bounds; a phase wrapped). How an
    // optimiser's raw point is handed to someone who works in the box (Python).
    std::vector<double> in_box(std::span<const double> x) const;
};

// A sampled coordinate read into [0, 1] as `bounds` says.
double to_unit(double v, Bounds bounds);

// pagmo's default population for n parameters: 4 + floor(3 ln n) (Hansen),
// raised to `at_least`.
int default_population(std::size_t dimension, int at_least);

} // namespace cic::gait
