#include "cic/experiments/experiment.hpp"

#include <algorithm>

#include "cic/core/process_pool.hpp"
#include "cic/experiments/gait/setup.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/experiments/symreg/problem.hpp"

namespace cic::experiments {

std::unique_ptr<Experiment> make_symreg_experiment(const Context& ctx);
std::unique_ptr<Experiment> make_hypergp_experiment(const Context& ctx);

std::unique_ptr<Experiment> make_experiment(const Context& ctx) {
    switch (ctx.settings.experiment.type) {
    case io::ExperimentType::Symreg: return make_symreg_experiment(ctx);
    case io::ExperimentType::HyperGP: return make_hypergp_experiment(ctx);
    case io::ExperimentType::Gait: break;   // not a GP experiment: the app runs it (src/run/run_gait.cpp)
    }
    throw std::logic_error("make_experiment: the gait experiment has no GP evaluator");
}

std::unique_ptr<JobRunner> make_job_runner(const Context& ctx) {
    if (ctx.make_runner) return ctx.make_runner();
    PoolOptions opt;
    opt.workers = std::max(1, ctx.workers);
    opt.argv = {ctx.worker_executable, "worker", "--settings", ctx.settings_file.string()};
    opt.timeout_seconds = ctx.settings.experiment.worker_timeout;
    return std::make_unique<ProcessPool>(opt);
}

void check_inputs(const io::Settings& s) {
    switch (s.experiment.type) {
    case io::ExperimentType::Symreg: symreg::make_dataset(s.symreg, {}); return;
    case io::ExperimentType::HyperGP: hypergp::check_inputs(s); return;
    case io::ExperimentType::Gait: gait::check_inputs(s); return;
    }
}

} // namespace cic::experiments
