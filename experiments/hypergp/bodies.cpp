// Several bodies in one fitness (bodies.hpp), and one worker job's evaluation
// (model.hpp's evaluate_job), which is where they are scored.
#include "cic/experiments/hypergp/bodies.hpp"

#include <algorithm>
#include <stdexcept>

#include "cic/experiments/hypergp/model.hpp"

namespace cic::hypergp {

double aggregate_fitness(std::span<const double> fitness, io::BodiesAggregate how) {
    if (fitness.empty()) throw std::invalid_argument("aggregate_fitness: no bodies");
    if (how == io::BodiesAggregate::Min) return *std::min_element(fitness.begin(), fitness.end());
    double sum = 0.0;
    for (double f : fitness) sum += f;
    return sum / static_cast<double>(fitness.size());
}

Outcome evaluate_job(const Model& m, const io::Settings& s, const Job& job, const Score& score,
                     const WalkNeeds& needs) {
    const sim::EvalOptions options = options_for(needs, job.descriptor);
    Outcome o = run(m, job.genotype, job.offsets, options);
    apply_score(o, score, m, s);
    if (m.extra_robots.empty() || o.failed) return o;
    // The other bodies, in order. A body whose physics fails fails the
    // genotype (the failure fitness): a score of the others alone would not be
    // the stated aggregate.
    o.body_fitness = {o.fitness};
    for (const sim::RobotSpec& robot : m.extra_robots) {
        Model one{robot, m.sim, m.neural, {}, m.aggregate, {}};
        Outcome b = run(one, job.genotype, job.offsets, options);
        apply_score(b, score, one, s);
        if (b.failed) {
            o.failed = true;
            o.failure = "body " + robot.name + ": " + b.failure;
            o.fitness = m.sim.failure_fitness;
            return o;
        }
        o.body_fitness.push_back(b.fitness);
    }
    o.fitness = aggregate_fitness(o.body_fitness, m.aggregate);
    return o;
}

} // namespace cic::hypergp
