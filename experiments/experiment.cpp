#include "cic/experiments/experiment.hpp"

#include <algorithm>

#include "cic/core/process_pool.hpp"
#include "cic/experiments/map_elites_emitters.hpp"
#include "cic/experiments/registry.hpp"

namespace cic::experiments {

std::unique_ptr<Experiment> make_experiment(const Context& ctx) {
    const ExperimentKind& kind = experiment_kind(ctx.settings.experiment.type);
    // The gait family has no GP evaluator: its search evaluates gait vectors (src/search/evolution_strategy.cpp).
    if (!kind.make) throw std::logic_error("make_experiment: type '" + kind.type.name + "' has no GP evaluator");
    return kind.make(ctx);
}

std::unique_ptr<JobRunner> make_job_runner(const Context& ctx) {
    if (ctx.make_runner) return ctx.make_runner();
    PoolOptions opt;
    opt.workers = std::max(1, ctx.workers);
    opt.argv = {ctx.worker_executable, "worker", "--settings", ctx.settings_file.string()};
    opt.timeout_seconds = ctx.settings.experiment.worker_timeout;
    opt.interrupted = ctx.interrupted;
    return std::make_unique<ProcessPool>(opt);
}

void check_inputs(const io::Settings& s) {
    const ExperimentKind& kind = experiment_kind(s.experiment.type);
    if (kind.check_inputs) kind.check_inputs(s);
    check_emitter(s);
}

} // namespace cic::experiments
