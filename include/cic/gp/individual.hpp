#pragma once
// Individual and Population (thesis 6.3.1-6.3.2): plain data that the
// stages of the evolution loop (evolution.hpp) read and change.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cic/gp/config.hpp"
#include "cic/tree/tree.hpp"

namespace cic::gp {

// A forest's depth as GP.forestDepth measures it: its trees' depths summed, or the deepest.
inline int forest_depth(const tree::Forest& forest, ForestDepth measure) {
    return measure == ForestDepth::Sum ? tree::total_depth(forest) : tree::max_depth(forest);
}

// Whatever an experiment decodes a genotype into (e.g. a substrate network).
struct Phenotype {
    virtual ~Phenotype() = default;
};

struct Individual {
    std::uint64_t id = 0;                    // unique within a run
    tree::Forest genotype;
    // Genes encoded directly beside the trees (GpConfig::direct; Offset-HybrID's
    // per-hinge offsets), part of the genotype: empty unless the run has them.
    std::vector<double> direct;
    std::shared_ptr<const Phenotype> phenotype;  // optional, not saved
    double fitness = 0.0;
    bool evaluated = false;
    std::vector<std::uint64_t> parents;      // ids; empty for generated ones
    // Marks, saved in population files as <attribute key="...">:
    bool illegal = false;     // over a heavy variant's lowered limit (thesis 5.2): breeds only if better
    bool failed = false;      // its evaluation failed (physics blow-up, worker); fitness is failureFitness
    std::string failure;      // why it failed, when it did
    bool edited = false;      // its trees were changed by hand in a population file, so it is evaluated again
    // The behaviour descriptor its evaluation measured, when one was asked for
    // (MAP-Elites, map_elites.hpp); not saved in population files.
    std::vector<double> descriptor;
    std::size_t size() const { return tree::total_size(genotype); }
    int depth(ForestDepth measure) const { return forest_depth(genotype, measure); }
};

using IndividualPtr = std::shared_ptr<Individual>;

class Population {
public:
    std::vector<IndividualPtr> individuals;
    int generation = 0;                      // 0 = the initial population

    auto begin() { return individuals.begin(); }
    auto end() { return individuals.end(); }
    auto begin() const { return individuals.begin(); }
    auto end() const { return individuals.end(); }
    std::size_t size() const { return individuals.size(); }
    bool empty() const { return individuals.empty(); }
    Individual& operator[](std::size_t i) { return *individuals[i]; }
    const Individual& operator[](std::size_t i) const { return *individuals[i]; }

    // Best by fitness; ties go to the smaller genotype, then the lower id.
    const Individual& best() const;
};

// Order used everywhere for "better": higher fitness, then smaller size, then lower id.
bool better(const Individual& a, const Individual& b);

} // namespace cic::gp
