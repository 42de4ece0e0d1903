// Registers the `gait` type: an open-loop gait or a CPG's weights tuned by a
// pagmo2 optimiser (experiments/gait/). Its search by default is the
// evolution strategy (src/search/evolution_strategy.cpp); its workers serve `gait` and `cpg` jobs.
#include "cic/experiments/gait/setup.hpp"
#include "cic/experiments/registry.hpp"
#include "cic/sim/job_text.hpp"

namespace cic::experiments {
namespace {

const Registrar registrar{{
    .type = *io::find_experiment_type("gait"),
    .keys = {},
    .check_inputs = &gait::check_inputs,
    .make = {},
    .job_kinds = {{"gait", [](const WorkerContext&) -> JobHandler { return &sim::run_gait_job; }},
                  {"cpg", [](const WorkerContext&) -> JobHandler { return &sim::run_cpg_job; }}},
}};

} // namespace
} // namespace cic::experiments
