#pragma once
// HyperGP's CPG substrate (Neural.substrate = cpg; docs/hypergp.md): the
// genotype gives the weights of a sim::CpgController, queried at the joints'
// substrate coordinates p_i as Revolve2's CPPN-driven CPG brains are:
//   w_i  = s tanh(T_0(p_i, p_i))                     (own frequency, rad/s)
//   w_ij = s tanh(T_0(p_i, p_j))  for i < j coupled  (w_ji = -w_ij)
//   g_i  = s_fb tanh(T_(1 mod n)(p_i, FB))           (feedback; only when s_fb > 0)
// with s = cpgWeightScale, s_fb = cpgFeedback, n the forest size, FB the
// feedback parameter point (queries.hpp), and joints coupled when their
// modules are at most cpgHops links apart in the body tree.
#include "cic/nn/config.hpp"
#include "cic/sim/cpg.hpp"
#include "cic/sim/robot.hpp"
#include "cic/tree/tree.hpp"

namespace cic::hypergp {

// Throws std::invalid_argument for an empty forest or a tree that does not fit
// the CPPF (see queries.hpp), a robot without joints, or control_step <= 0.
sim::CpgSpec cpg_spec(const sim::RobotSpec& robot, const tree::Forest& genotype, const nn::NeuralConfig& cfg,
                      double control_step);

} // namespace cic::hypergp
