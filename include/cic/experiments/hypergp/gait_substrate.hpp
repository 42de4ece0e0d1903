#pragma once
// HyperGP-gait (Neural.substrate = gait; docs/hypergp.md): an indirect
// encoding of the open-loop gait that the `gait` experiment tunes directly.
// Joint i at substrate coordinates p_i gets, from a forest of n trees,
//   amplitude a_i = pi/2 unit(T_(0 mod n)(p_i, A))      in (0, pi/2)
//   phase     phi_i = pi tanh(T_(1 mod n)(p_i, P))      in (-pi, pi)
//   offset    o_i = pi/2 tanh(T_(2 mod n)(p_i, O))      in (-pi/2, pi/2)
// and the robot one frequency f = evolved_frequency (T_0 at (F, F)), so that
// desired_i(t) = o_i + a_i sin(2 pi f t + phi_i) (sim::GaitController). A
// forest of three trees gives each parameter its own tree; one tree tells the
// parameters apart by the point A, P or O it is asked at (queries.hpp).
//
// Offset-HybrID (Neural.directOffsets; Helms & Clune 2017): the genotype also
// holds one number d_i per joint, encoded directly, added to the tree's offset
// in units of the servo's half range pi/2:
//   offset    o_i = pi/2 clamp(tanh(T_(2 mod n)(p_i, O)) + d_i, -1, 1)
// so any posture is reachable whatever the tree says (d_i in [-2, 2],
// kOffsetLimit). Without offsets the formula above is unchanged, bit for bit.
#include <span>
#include <vector>

#include "cic/nn/config.hpp"
#include "cic/sim/controller.hpp"
#include "cic/sim/robot.hpp"
#include "cic/tree/tree.hpp"

namespace cic::hypergp {

// Throws std::invalid_argument for an empty forest, a tree that does not fit
// the CPPF, or a robot without joints.
// `offsets` empty, or one per joint (std::invalid_argument otherwise, or for a
// non-finite one).
sim::GaitSpec gait_spec(const sim::RobotSpec& robot, const tree::Forest& genotype, const nn::NeuralConfig& cfg,
                        std::span<const double> offsets = {});

// Switch-HybrID's hand-over (docs/hypergp.md): the same gait as a point of the
// gait experiment's unit box in its centred layout (gait/encoding.hpp, with
// Gait.frequencyMin/Max = Neural.frequencyMin/Max and no second harmonic):
// x[0] = unit(T_0(F, F)), then per joint u_a, t_p / 2, s_o / 2. Decoded, it
// gives gait_spec's numbers bit for bit. Throws like gait_spec.
std::vector<double> gait_box_point(const sim::RobotSpec& robot, const tree::Forest& genotype,
                                   const nn::NeuralConfig& cfg, std::span<const double> offsets = {});

// The range of a direct offset, in units of pi/2: [-kOffsetLimit, kOffsetLimit].
inline constexpr double kOffsetLimit = 2.0;

} // namespace cic::hypergp
