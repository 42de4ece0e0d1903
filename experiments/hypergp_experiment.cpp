// HyperGP wiring (thesis 6.2.2): genotypes are evaluated in `cic worker`
// processes, or on whatever runner the app hands over in Context::make_runner
// (MPI ranks). Physics runs in separate processes because ODE's QuickStep uses
// process-global random state; each evaluation resets it, so any number of
// workers gives the same fitness bits, and every runner gives the same reply.
#include <fmt/format.h>

#include "cic/experiments/experiment.hpp"
#include "cic/experiments/hypergp/model.hpp"

namespace cic::experiments {
namespace {

class HypergpEvaluator final : public gp::Evaluator {
public:
    // Jobs go to make_job_runner's runner: worker processes, or MPI ranks.
    HypergpEvaluator(const Context& ctx)
        : model_(hypergp::Model::from_settings(ctx.settings)), warn_(ctx.warn), pool_(make_job_runner(ctx)) {}

    void evaluate(std::span<const gp::IndividualPtr> todo) override {
        std::vector<std::string> jobs;
        jobs.reserve(todo.size());
        for (const auto& ind : todo) jobs.push_back("hypergp\n" + hypergp::job_body(ind->genotype));
        const auto results = pool_->run(jobs);
        for (const auto& note : pool_->take_notes()) warn_("warning: " + note);
        for (std::size_t i = 0; i < todo.size(); ++i) {
            auto& ind = *todo[i];
            const JobResult& r = results[i];
            for (const auto& t : r.trouble)
                warn_(fmt::format("warning: individual {}: {}{}", ind.id, t, r.ok || &t != &r.trouble.back()
                                                                                 ? ", job retried" : ""));
            if (r.ok) {
                const sim::EvalReply reply = sim::parse_eval_reply(r.output);
                ind.fitness = reply.fitness;
                if (reply.failed) {
                    ind.failed = true;
                    ind.failure = reply.failure;
                }
            } else {
                ind.fitness = model_.sim.failure_fitness;
                ind.failed = true;
                ind.failure = "worker: " + r.error;
                warn_(fmt::format("warning: individual {} scored as failed (fitness {}): {}", ind.id, ind.fitness,
                                  r.error));
            }
            ind.evaluated = true;
        }
    }

    const hypergp::Model& model() const { return model_; }

private:
    hypergp::Model model_;
    std::function<void(const std::string&)> warn_;
    std::unique_ptr<JobRunner> pool_;
};

class HypergpExperiment final : public Experiment {
public:
    explicit HypergpExperiment(const Context& ctx) : eval_(ctx) {}
    gp::Evaluator& evaluator() override { return eval_; }
    std::string describe(const gp::Individual& ind) const override {
        return fmt::format("robot {} ({} modules)", eval_.model().robot.name, eval_.model().robot.modules.size()) +
               (ind.failed ? " [failed: " + ind.failure + "]" : "");
    }

private:
    HypergpEvaluator eval_;
};

} // namespace

std::unique_ptr<Experiment> make_hypergp_experiment(const Context& ctx) {
    return std::make_unique<HypergpExperiment>(ctx);
}

} // namespace cic::experiments
