#pragma once
// The gait experiment's CPG genotype (Gait.controller = cpg): the weights of
// HyperGP's cpg substrate (sim/cpg.hpp), tuned directly, the direct twin of
// HyperGP-CPG. A point of the unit box [0, 1]^n, read as Bounds says, holds
//   w_i  = (2x - 1) s      one per joint
//   w_ab = (2x - 1) s      one per coupled pair (sim::cpg_neighbours)
//   g_i  = (2x - 1) s_fb   one per joint, only when s_fb > 0
// in that order, with s = Neural.cpgWeightScale and s_fb = Neural.cpgFeedback:
// the ranges HyperGP's tanh maps into.
#include <cstddef>
#include <span>
#include <vector>

#include "cic/nn/config.hpp"
#include "cic/sim/cpg.hpp"
#include "cic/sim/robot.hpp"
#include "cic/experiments/gait/encoding.hpp"

namespace cic::gait {

struct CpgEncoding {
    std::size_t joints = 0;
    std::vector<sim::CpgEdge> edges;
    double weight_scale = 1.0;
    double feedback_scale = 0.0;
    double control_step = 0.0125;
    Bounds bounds = Bounds::Clamp;

    // The robot's joints and neighbourhood (cfg.cpg_hops). Throws
    // std::invalid_argument for a robot without joints or a bad scale or step.
    CpgEncoding(const sim::RobotSpec& robot, const nn::NeuralConfig& cfg, double control_step, Bounds bounds);

    std::size_t dimension() const { return joints + edges.size() + (feedback_scale > 0 ? joints : 0); }
    // Throws std::invalid_argument when x.size() != dimension() or x holds a non-finite value.
    sim::CpgSpec decode(std::span<const double> x) const;
    // The point of the unit box that decodes to the same CPG, bit for bit (Encoding::in_box).
    std::vector<double> in_box(std::span<const double> x) const;
};

} // namespace cic::gait
