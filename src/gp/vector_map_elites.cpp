#include "cic/gp/vector_map_elites.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cic::gp {

void VectorMapElitesConfig::validate() const {
    grid.validate();
    if (dimension < 1) throw std::invalid_argument("map-elites: dimension must be at least 1");
    if (batch < 1) throw std::invalid_argument("map-elites: batch must be at least 1");
    if (initial < 1) throw std::invalid_argument("map-elites: initial must be at least 1");
    if (!(sigma > 0) || !std::isfinite(sigma)) throw std::invalid_argument("map-elites: sigma must be a number > 0");
}

VectorMapElites::VectorMapElites(VectorMapElitesConfig config, std::uint64_t seed)
    : config_((config.validate(), std::move(config))), archive_(config_.grid), rng_(seed) {}

std::vector<double> VectorMapElites::random_point() {
    std::vector<double> x(config_.dimension);
    for (double& v : x) v = rng_.uniform();
    return x;
}

std::vector<double> VectorMapElites::mutant() {
    std::vector<double> x = archive_.at(archive_.random_cell(rng_))->solution;
    for (double& v : x) v = std::clamp(v + config_.sigma * rng_.normal(), 0.0, 1.0);
    return x;
}

int VectorMapElites::step(const VectorBatch& evaluate, long budget_left) {
    if (budget_left < 1) throw std::invalid_argument("map-elites: no evaluation left in the budget");
    const long size = std::min<long>(config_.batch, budget_left);
    std::vector<std::vector<double>> xs;
    xs.reserve(static_cast<std::size_t>(size));
    // Uniform points until `initial` have been evaluated (or while the archive
    // is still empty: every one so far failed), mutants of elites after.
    for (long i = 0; i < size; ++i)
        xs.push_back(evaluations_ + i < config_.initial || archive_.empty() ? random_point() : mutant());
    const std::vector<Evaluation> results = evaluate(xs);
    if (results.size() != xs.size())
        throw std::logic_error("map-elites: " + std::to_string(results.size()) + " results for a batch of " +
                               std::to_string(xs.size()));
    int kept = 0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        if (results[i].failed) {
            ++failed_;
            continue;
        }
        if (archive_.offer(results[i].descriptor, results[i].fitness, std::move(xs[i]))) ++kept;
    }
    evaluations_ += size;
    ++batches_;
    return kept;
}

void VectorMapElites::restore(const std::map<std::size_t, Archive::Elite>& elites, long evaluations, long failed,
                              int batches, const Rng::State& rng) {
    if (evaluations < 0 || failed < 0 || failed > evaluations || batches < 0)
        throw std::invalid_argument("map-elites: counters out of range");
    Archive archive(config_.grid);
    for (const auto& [cell, e] : elites) {
        if (e.solution.size() != config_.dimension)
            throw std::invalid_argument("map-elites: an elite of " + std::to_string(e.solution.size()) +
                                        " parameters for a dimension of " + std::to_string(config_.dimension));
        archive.restore(cell, e);
    }
    archive_ = std::move(archive);
    evaluations_ = evaluations;
    failed_ = failed;
    batches_ = batches;
    rng_.set_state(rng);
}

} // namespace cic::gp
