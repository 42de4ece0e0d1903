// HyperGP wiring (thesis 6.2.2), and the `hypergp` type's registration:
// genotypes are evaluated in `cic worker`
// processes, or on whatever runner the app hands over in Context::make_runner
// (MPI ranks). Physics runs in separate processes because ODE's QuickStep uses
// process-global random state; each evaluation resets it, so any number of
// workers gives the same fitness bits, and every runner gives the same reply.
#include <string_view>
#include <unordered_map>

#include <fmt/format.h>

#include "cic/experiments/hypergp/experiment.hpp"
#include "cic/experiments/registry.hpp"
#include "cic/experiments/hypergp/model.hpp"

namespace cic::experiments {
namespace {

class HypergpEvaluator final : public gp::Evaluator {
public:
    // Jobs go to make_job_runner's runner: worker processes, or MPI ranks.
    HypergpEvaluator(const Context& ctx, std::string job_kind)
        : model_(hypergp::Model::from_settings(ctx.settings)), job_kind_(std::move(job_kind)), warn_(ctx.warn),
          pool_(make_job_runner(ctx)),
          descriptor_(ctx.settings.map_elites.enabled ? ctx.settings.map_elites.descriptor : sim::Descriptor::None) {}

    // Evaluation is a pure function of the job text (the genotype), so a
    // genotype met again in this session reuses its result instead of another
    // simulation: the same bytes, less time (7 % of the default R1 run's
    // evaluations, seed 1; README "Determinism").
    // Worker failures are not kept: they are not the genotype's doing.
    void evaluate(std::span<const gp::IndividualPtr> todo) override {
        std::vector<std::string> jobs;
        std::vector<std::size_t> job_of(todo.size());   // index into jobs, or kCached
        std::unordered_map<std::string_view, std::size_t> queued;
        std::vector<std::string> bodies(todo.size());
        for (std::size_t i = 0; i < todo.size(); ++i) {
            bodies[i] = job_kind_ + "\n" + hypergp::job_body(todo[i]->genotype, descriptor_, todo[i]->direct, body_);
            if (auto hit = cache_.find(bodies[i]); hit != cache_.end()) {
                apply(*todo[i], hit->second);
                job_of[i] = kCached;
                ++reused_;
            } else if (auto q = queued.find(bodies[i]); q != queued.end()) {
                job_of[i] = q->second;
                ++reused_;
            } else {
                job_of[i] = jobs.size();
                queued.emplace(bodies[i], jobs.size());
                jobs.push_back(bodies[i]);
            }
        }
        const auto results = jobs.empty() ? std::vector<JobResult>{} : pool_->run(jobs);
        for (const auto& note : pool_->take_notes()) warn_("warning: " + note);
        std::vector<bool> reported(jobs.size(), false);
        for (std::size_t i = 0; i < todo.size(); ++i) {
            if (job_of[i] == kCached) continue;
            auto& ind = *todo[i];
            const JobResult& r = results[job_of[i]];
            const bool first = !reported[job_of[i]];
            reported[job_of[i]] = true;
            if (first)
                for (const auto& t : r.trouble)
                    warn_(fmt::format("warning: individual {}: {}{}", ind.id, t,
                                      r.ok || &t != &r.trouble.back() ? ", job retried" : ""));
            const sim::EvalReply reply = sim::reply_of(r, model_.sim.failure_fitness);
            apply(ind, reply);
            if (r.ok && first) cache_.emplace(bodies[i], reply);   // worker failures are not the genotype's doing
            if (!r.ok)
                warn_(fmt::format("warning: individual {} scored as failed (fitness {}): {}", ind.id, ind.fitness,
                                  r.error));
        }
        simulated_ += static_cast<long>(jobs.size());
    }

    // "N evaluations: M simulated, K reused" for run.log.
    std::string session_note() const {
        return fmt::format("evaluations this session: {} simulated, {} reused a result of the same genotype",
                           simulated_, reused_);
    }

    const hypergp::Model& model() const { return model_; }

    // A growing robot's next body: its jobs say which (hypergp::job_body), so
    // a result is never reused across bodies.
    void use_body(std::size_t body) {
        body_robot_ = model_.on_body(body).robot;
        body_ = body;
    }
    const sim::RobotSpec& robot() const { return body_ == 0 ? model_.robot : body_robot_; }

private:
    static constexpr std::size_t kCached = static_cast<std::size_t>(-1);

    static void apply(gp::Individual& ind, const sim::EvalReply& reply) {
        ind.fitness = reply.fitness;
        ind.failed = reply.failed;
        ind.failure = reply.failed ? reply.failure : std::string();
        ind.descriptor = reply.descriptor;
        ind.evaluated = true;
    }

    hypergp::Model model_;
    std::string job_kind_;
    std::function<void(const std::string&)> warn_;
    std::unique_ptr<JobRunner> pool_;
    sim::Descriptor descriptor_;   // asked of every job (MAP-Elites), else None
    std::size_t body_ = 0;         // a growing robot's current body (0 = the robot)
    sim::RobotSpec body_robot_;    // that body, when not 0
    std::unordered_map<std::string, sim::EvalReply> cache_;   // job text -> reply, for this session
    long simulated_ = 0, reused_ = 0;
};

class HypergpExperiment final : public Experiment {
public:
    HypergpExperiment(const Context& ctx, std::string job_kind) : eval_(ctx, std::move(job_kind)) {}
    gp::Evaluator& evaluator() override { return eval_; }
    std::string describe(const gp::Individual& ind) const override {
        const auto& m = eval_.model();
        std::string bodies;   // several bodies in one fitness (bodies.hpp)
        for (const auto& r : m.extra_robots) bodies += (bodies.empty() ? "" : ", ") + r.name;
        if (!bodies.empty())
            bodies = fmt::format(" and {} ({} of the bodies' fitnesses)", bodies,
                                 m.aggregate == io::BodiesAggregate::Min ? "minimum" : "mean");
        return fmt::format("robot {} ({} modules){}", eval_.robot().name, eval_.robot().modules.size(), bodies) +
               (ind.failed ? " [failed: " + ind.failure + "]" : "");
    }
    std::string session_note() const override { return eval_.session_note(); }
    gp::DirectGenes direct_genes() const override { return hypergp::direct_offset_genes(eval_.model()); }
    void use_body(std::size_t body) override { eval_.use_body(body); }

private:
    HypergpEvaluator eval_;
};

const Registrar registrar{{
    .type = *io::find_experiment_type("hypergp"),
    .keys = {},
    .check_inputs = &hypergp::check_inputs,
    .make = [](const Context& ctx) { return make_hypergp_experiment(ctx, "hypergp"); },
    .job_kinds = {{"hypergp",
                   [](const WorkerContext& w) {
                       return hypergp::make_job_handler([w] { return w.load_settings(); });
                   }}},
}};

} // namespace

std::unique_ptr<Experiment> make_hypergp_experiment(const Context& ctx, std::string job_kind) {
    return std::make_unique<HypergpExperiment>(ctx, std::move(job_kind));
}

} // namespace cic::experiments
