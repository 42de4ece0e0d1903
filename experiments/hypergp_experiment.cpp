// HyperGP wiring (thesis 6.2.2): genotypes are evaluated in-process with one
// worker, in `cic worker` processes with more, or on whatever runner the app
// hands over in Context::make_runner (MPI ranks). Physics runs in separate
// processes because ODE's QuickStep uses process-global random state; each
// evaluation resets it, so any number of workers gives the same fitness bits.
#include <fmt/format.h>

#include "cic/core/process_pool.hpp"
#include "experiments/experiment.hpp"
#include "experiments/hypergp/model.hpp"

namespace cic::experiments {
namespace {

class HypergpEvaluator final : public gp::Evaluator {
public:
    HypergpEvaluator(const Context& ctx) : model_(hypergp::Model::from_settings(ctx.settings)) {
        if (ctx.make_runner) {
            pool_ = ctx.make_runner();
        } else if (ctx.workers > 1) {
            PoolOptions opt;
            opt.workers = ctx.workers;
            opt.argv = {ctx.worker_executable, "worker", "--settings", ctx.settings_file.string()};
            opt.timeout_seconds = ctx.settings.experiment.worker_timeout;
            pool_ = std::make_unique<ProcessPool>(opt);
        }
    }

    void evaluate(std::span<const gp::IndividualPtr> todo) override {
        if (!pool_) {
            for (const auto& ind : todo) store(*ind, hypergp::run(model_, ind->genotype));
            return;
        }
        std::vector<std::string> jobs;
        jobs.reserve(todo.size());
        for (const auto& ind : todo) jobs.push_back("hypergp\n" + hypergp::job_body(ind->genotype));
        const auto results = pool_->run(jobs);
        for (std::size_t i = 0; i < todo.size(); ++i) {
            auto& ind = *todo[i];
            if (results[i].ok) {
                const auto r = hypergp::parse_reply(results[i].output);
                ind.fitness = r.fitness;
                if (r.failed) ind.attributes["failed"] = "physics";
            } else {
                ind.fitness = model_.sim.failure_fitness;
                ind.attributes["failed"] = "worker: " + results[i].error;
            }
            ind.evaluated = true;
        }
    }

    const hypergp::Model& model() const { return model_; }

private:
    void store(gp::Individual& ind, const hypergp::Outcome& o) const {
        ind.fitness = o.fitness;
        if (o.failed) ind.attributes["failed"] = o.failure;
        ind.evaluated = true;
    }

    hypergp::Model model_;
    std::unique_ptr<JobRunner> pool_;   // null: evaluate in this process
};

class HypergpExperiment final : public Experiment {
public:
    explicit HypergpExperiment(const Context& ctx) : eval_(ctx) {}
    gp::Evaluator& evaluator() override { return eval_; }
    std::string describe(const gp::Individual& ind) const override {
        return fmt::format("robot {} ({} modules)", eval_.model().robot.name, eval_.model().robot.modules.size()) +
               (ind.has("failed") ? " [failed: " + ind.attributes.at("failed") + "]" : "");
    }

private:
    HypergpEvaluator eval_;
};

} // namespace

std::unique_ptr<Experiment> make_hypergp_experiment(const Context& ctx) {
    return std::make_unique<HypergpExperiment>(ctx);
}

} // namespace cic::experiments
