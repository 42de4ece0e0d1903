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
#include "cic/nn/config.hpp"
#include "cic/sim/controller.hpp"
#include "cic/sim/robot.hpp"
#include "cic/tree/tree.hpp"

namespace cic::hypergp {

// Throws std::invalid_argument for an empty forest, a tree that does not fit
// the CPPF, or a robot without joints.
sim::GaitSpec gait_spec(const sim::RobotSpec& robot, const tree::Forest& genotype, const nn::NeuralConfig& cfg);

} // namespace cic::hypergp
