#pragma once
// Private to src/report: one genotype replayed with the evaluation's own code
// path (the functions a worker's job handler calls, ODE's random state reset
// for each), for replay.cpp and verify.cpp.
#include <span>
#include <vector>

#include "cic/experiments/gait/setup.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/io/settings.hpp"
#include "cic/report/replay.hpp"
#include "cic/sim/config.hpp"

namespace cic::report::detail {

int centre_body_of(const sim::RobotSpec& robot);
// One gait vector of the settings' gait, walked (and recorded at `fps` > 0);
// with a descriptor, item.descriptor holds its values as a worker computes them.
ReplayItem replay_point(const gait::Setup& setup, const std::vector<double>& x, double fps, bool trace,
                        sim::Descriptor descriptor = sim::Descriptor::None);
// One HyperGP genotype (with its direct genes, if any), scored as the run's type scores it.
ReplayItem replay_trees(const hypergp::Model& model, const io::Settings& settings, const tree::Forest& genotype,
                        std::span<const double> offsets, double fps, bool trace,
                        sim::Descriptor descriptor = sim::Descriptor::None);

} // namespace cic::report::detail
