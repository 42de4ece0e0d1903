#pragma once
// The HyperGP family's experiment, for the `hypergp` type and for types that
// score the same controllers differently (examples/plugin): genotypes go to
// worker processes (or MPI ranks) as `job_kind` jobs, whose handler a type
// registers (hypergp::make_job_handler with its own score).
#include <memory>
#include <string>

#include "cic/experiments/experiment.hpp"

namespace cic::experiments {

std::unique_ptr<Experiment> make_hypergp_experiment(const Context& ctx, std::string job_kind);

} // namespace cic::experiments
