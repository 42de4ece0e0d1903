// Gait experiment wiring (see setup.hpp).
#include "cic/experiments/gait/setup.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "cic/core/error.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/sim/job_text.hpp"
#include "cic/experiments/hypergp/model.hpp"

namespace cic::gait {

Optimizer optimizer_of(io::GaitOptimizer o) {
    switch (o) {
    case io::GaitOptimizer::Cmaes: return Optimizer::Cmaes;
    case io::GaitOptimizer::Xnes: return Optimizer::Xnes;
    case io::GaitOptimizer::Sade: return Optimizer::Sade;
    case io::GaitOptimizer::Sepcmaes: return Optimizer::Sepcmaes;
    }
    return Optimizer::Cmaes;
}

Setup Setup::from_settings(const io::Settings& s) {
    const hypergp::Model model = hypergp::Model::from_settings(s);   // the same robot HyperGP would drive
    const std::size_t joints = model.robot.actuated().size();
    if (joints == 0) throw InputError("the robot " + model.robot.name + " has no joint to drive");
    Setup out{model.robot, model.sim,
              Encoding(joints, s.gait.second_harmonic, s.gait.frequency_min, s.gait.frequency_max,
                       s.gait.bounds == io::GaitBounds::Reflect ? Bounds::Reflect : Bounds::Clamp),
              std::nullopt};
    out.encoding.centred = s.neural.switches();   // Switch-HybrID's gait phase (encoding.hpp)
    if (s.gait.controller == io::GaitController::Cpg)
        out.cpg.emplace(model.robot, s.neural, model.sim.sample_step, out.encoding.bounds);
    out.optimizer = optimizer_of(s.gait.optimizer);
    out.population = s.gait.population_size > 0
        ? s.gait.population_size
        : default_population(out.dimension(), out.optimizer == Optimizer::Sade ? 7 : 5);
    out.sigma0 = s.gait.sigma0;
    if (out.population > s.gait.evaluations)
        throw io::key_error(s, {"Gait.evaluations"},
                            fmt::format("a budget of {} does not cover one generation of {} candidates",
                                        s.gait.evaluations, out.population));
    return out;
}

void check_inputs(const io::Settings& s) {
    hypergp::check_inputs(s);   // robot file or preset, with a joint
    (void)Setup::from_settings(s);
}

std::unique_ptr<sim::Controller> Setup::controller(std::span<const double> x) const {
    if (cpg) return std::make_unique<sim::CpgController>(cpg->decode(x));
    return std::make_unique<sim::GaitController>(encoding.decode(x));
}

std::string Setup::describe(std::span<const double> x) const {
    if (cpg) {
        const sim::CpgSpec c = cpg->decode(x);
        std::string out = "CPG weights w_i";
        for (double w : c.self) out += fmt::format(" {:.3f}", w);
        out += "; couplings";
        for (std::size_t k = 0; k < c.edges.size(); ++k)
            out += fmt::format(" {}-{}:{:.3f}", c.edges[k].a, c.edges[k].b, c.coupling[k]);
        if (!c.feedback.empty()) {
            out += "; feedback";
            for (double g : c.feedback) out += fmt::format(" {:.3f}", g);
        }
        return out;
    }
    const sim::GaitSpec g = encoding.decode(x);
    std::string out = fmt::format("frequency {:.4f} Hz; per joint amplitude/phase/offset", g.frequency);
    for (const auto& j : g.joints) {
        out += fmt::format(" [{:.3f} {:.3f} {:.3f}", j.amplitude, j.phase, j.offset);
        if (j.amplitude2 != 0 || j.phase2 != 0) out += fmt::format(" {:.3f} {:.3f}", j.amplitude2, j.phase2);
        out += "]";
    }
    return out;
}

std::string make_job(const Setup& setup, std::span<const double> x, sim::Descriptor descriptor) {
    if (setup.cpg) return sim::make_cpg_job(setup.robot, setup.sim, setup.cpg->decode(x), descriptor);
    return sim::make_gait_job(setup.robot, setup.sim, setup.encoding.decode(x), descriptor);
}

Evaluator::Evaluator(const experiments::Context& ctx, const Setup& setup)
    : setup_(setup), warn_(ctx.warn), runner_(experiments::make_job_runner(ctx)) {}

Evaluator::~Evaluator() = default;

std::vector<sim::EvalReply> Evaluator::replies(const std::vector<std::vector<double>>& xs, sim::Descriptor descriptor) {
    std::vector<std::string> jobs;
    jobs.reserve(xs.size());
    for (const auto& x : xs) jobs.push_back(make_job(setup_, x, descriptor));
    const auto results = runner_->run(jobs);
    for (const auto& note : runner_->take_notes()) warn_("warning: " + note);
    std::vector<sim::EvalReply> replies(xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) {
        const JobResult& r = results[i];
        for (const auto& t : r.trouble) warn_(fmt::format("warning: candidate {}: {}", i, t));
        replies[i] = sim::reply_of(r, setup_.sim.failure_fitness);
        if (replies[i].failed) ++failed_;
        if (!r.ok)
            warn_(fmt::format("warning: candidate {} scored as failed (fitness {}): {}", i, replies[i].fitness, r.error));
    }
    return replies;
}

std::vector<double> Evaluator::operator()(const std::vector<std::vector<double>>& xs) {
    std::vector<double> f;
    for (const sim::EvalReply& r : replies(xs, sim::Descriptor::None)) f.push_back(r.fitness);
    return f;
}

std::vector<gp::Evaluation> Evaluator::described(const std::vector<std::vector<double>>& xs,
                                                 sim::Descriptor descriptor) {
    std::vector<gp::Evaluation> out;
    for (sim::EvalReply& r : replies(xs, descriptor)) out.push_back({r.fitness, std::move(r.descriptor), r.failed});
    return out;
}

} // namespace cic::gait
