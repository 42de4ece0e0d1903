// Gait experiment wiring (see setup.hpp).
#include "cic/experiments/gait/setup.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "cic/core/error.hpp"
#include "cic/sim/job_text.hpp"
#include "cic/experiments/hypergp/model.hpp"

namespace cic::gait {

Optimizer optimizer_of(io::GaitOptimizer o) {
    switch (o) {
    case io::GaitOptimizer::Cmaes: return Optimizer::Cmaes;
    case io::GaitOptimizer::Xnes: return Optimizer::Xnes;
    case io::GaitOptimizer::Sade: return Optimizer::Sade;
    }
    return Optimizer::Cmaes;
}

Setup Setup::from_settings(const io::Settings& s) {
    const hypergp::Model model = hypergp::Model::from_settings(s);   // the same robot HyperGP would drive
    const std::size_t joints = model.robot.actuated().size();
    if (joints == 0) throw InputError("the robot " + model.robot.name + " has no joint to drive");
    Setup out{model.robot, model.sim,
              Encoding(joints, s.gait.second_harmonic, s.gait.frequency_min, s.gait.frequency_max,
                       s.gait.bounds == io::GaitBounds::Reflect ? Bounds::Reflect : Bounds::Clamp)};
    out.optimizer = optimizer_of(s.gait.optimizer);
    out.population = s.gait.population_size > 0
        ? s.gait.population_size
        : default_population(out.encoding.dimension(), out.optimizer == Optimizer::Sade ? 7 : 5);
    out.sigma0 = s.gait.sigma0;
    if (out.population > s.gait.evaluations)
        throw InputError(fmt::format("<Gait> evaluations: a budget of {} does not cover one generation of {} candidates",
                                     s.gait.evaluations, out.population));
    return out;
}

void check_inputs(const io::Settings& s) {
    hypergp::check_inputs(s);   // robot file or preset, with a joint
    (void)Setup::from_settings(s);
}

std::string make_job(const Setup& setup, std::span<const double> x) {
    return sim::make_gait_job(setup.robot, setup.sim, setup.encoding.decode(x));
}

Search resume_search(const Setup& setup, const io::GaitFile& g, const std::string& file) {
    Search search(setup.optimizer, setup.encoding.dimension(), setup.population, setup.sigma0, g.seed);
    try {
        search.replay(g.history, g.generation);
    } catch (const std::invalid_argument& e) {
        throw InputError(std::string("the checkpoint does not replay: ") + e.what(), file);
    }
    bool same = search.population().size() == g.population.size() && search.champion().x == g.champion.x &&
                search.champion().fitness == g.champion.fitness;
    for (std::size_t i = 0; same && i < g.population.size(); ++i)
        same = search.population()[i].x == g.population[i].x && search.population()[i].fitness == g.population[i].fitness;
    if (!same)
        throw InputError("replaying the checkpoint's history does not give its candidates (edited by hand, or made by "
                         "another version of cic or pagmo?)",
                         file);
    return search;
}

Evaluator::Evaluator(const experiments::Context& ctx, const Setup& setup)
    : setup_(setup), warn_(ctx.warn), runner_(experiments::make_job_runner(ctx)) {}

Evaluator::~Evaluator() = default;

std::vector<double> Evaluator::operator()(const std::vector<std::vector<double>>& xs) {
    std::vector<std::string> jobs;
    jobs.reserve(xs.size());
    for (const auto& x : xs) jobs.push_back(make_job(setup_, x));
    const auto results = runner_->run(jobs);
    for (const auto& note : runner_->take_notes()) warn_("warning: " + note);
    std::vector<double> f(xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) {
        const JobResult& r = results[i];
        for (const auto& t : r.trouble) warn_(fmt::format("warning: candidate {}: {}", i, t));
        if (r.ok) {
            const sim::EvalReply reply = sim::parse_eval_reply(r.output);
            f[i] = reply.fitness;
            if (reply.failed) ++failed_;
        } else {
            f[i] = setup_.sim.failure_fitness;
            ++failed_;
            warn_(fmt::format("warning: candidate {} scored as failed (fitness {}): {}", i, f[i], r.error));
        }
    }
    return f;
}

} // namespace cic::gait
