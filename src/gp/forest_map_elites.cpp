#include "cic/gp/forest_map_elites.hpp"

#include <memory>
#include <stdexcept>

#include "cic/gp/generators.hpp"
#include "cic/gp/operators.hpp"

namespace cic::gp {

Emitter<tree::Forest> forest_emitter(const GpConfig& cfg, const tree::PrimitiveSet& ps) {
    if (!(cfg.crossover_rate + cfg.mutation_rate > 0))
        throw std::invalid_argument("map-elites: crossover and mutation rates are both 0, so nothing varies an elite");
    // The generators of the GP loop's Initialise and Breed (evolution.cpp).
    const auto init = std::make_shared<TreeGenerator>(ps, cfg.init_method, cfg.expected_tree_size,
                                                      levels(cfg, cfg.init_method, cfg.min_init_depth),
                                                      cfg.generated_tree_levels());
    const int mutation_levels = levels(cfg, cfg.mutation_generator, cfg.max_mutation_depth);
    const auto grow = std::make_shared<TreeGenerator>(ps, cfg.mutation_generator, cfg.expected_tree_size, 1,
                                                      mutation_levels);
    const int trees = cfg.trees_per_genotype;
    const double p_crossover = cfg.crossover_rate / (cfg.crossover_rate + cfg.mutation_rate);
    const int cap = cfg.max_tree_depth, retries = cfg.duplicate_retries;
    const NodeSelection how = cfg.node_selection;

    Emitter<tree::Forest> e;
    e.random = [init, trees](Rng& rng) {
        tree::Forest f;
        for (int t = 0; t < trees; ++t) f.push_back(init->generate(rng));
        return f;
    };
    e.vary = [init, grow, trees, p_crossover, cap, retries, how, mutation_levels](
                 Rng& rng, const GridArchive<tree::Forest>& archive) {
        for (int attempt = 0; attempt <= retries; ++attempt) {
            const tree::Forest& a = archive.at(archive.random_cell(rng))->solution;
            tree::Forest child;
            if (rng.uniform() < p_crossover) {
                const tree::Forest& b = archive.at(archive.random_cell(rng))->solution;
                child = crossover(rng, a, b, how).first;
            } else {
                child = mutate(rng, a, *grow, mutation_levels, how);
            }
            if (cap == 0 || tree::max_depth(child) <= cap) return child;
        }
        tree::Forest f;   // every attempt broke the cap: a new genotype instead
        for (int t = 0; t < trees; ++t) f.push_back(init->generate(rng));
        return f;
    };
    e.check = [trees](const tree::Forest& f) {
        if (static_cast<int>(f.size()) != trees)
            throw std::invalid_argument("map-elites: an elite of " + std::to_string(f.size()) +
                                        " trees for genotypes of " + std::to_string(trees));
    };
    return e;
}

} // namespace cic::gp
