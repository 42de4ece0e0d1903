#pragma once
// Plain settings of the GP engine, with the thesis's defaults (Appendix B).
// Validation happens once, at the boundary (io/settings).
#include <cstddef>
#include <string>
#include <vector>

#include "cic/tree/primitives.hpp"

namespace cic::gp {

enum class InitMethod { Ptc1, Grow, Full, RampedHalfAndHalf };
enum class SelectionType { Tournament = 0, Roulette = 1 };
enum class BloatVariant { Simple = 0, Heavy = 1, VeryHeavy = 2 };
// How deep a forest is: the sum of its trees' depths (thesis 7.2.1, fig. 7.4b)
// or the depth of its deepest tree. A 1-tree genotype has the same depth either way.
enum class ForestDepth { Sum, Max };
// Which node crossover and mutation pick: Koza's rule (a function node with
// probability 0.9 when the tree has one, else a leaf) or any node alike.
enum class NodeSelection { Koza, Uniform };

// Real numbers encoded directly beside the trees (Offset-HybrID, Helms & Clune
// 2017; docs/hypergp.md): `count` genes in [-limit, limit] per individual,
// drawn from N(0, sigma) at initialisation, inherited with the trees of the
// child's first parent, and in every child of crossover or mutation each moved
// by N(0, sigma) with probability `rate`, then clamped. Reproduction copies and
// elites keep theirs. count 0 (the default) draws nothing: the plain GP's run.
// The experiment sets it (the genes' meaning is its own), not a settings key.
struct DirectGenes {
    std::size_t count = 0;
    double limit = 1.0;
    double sigma = 0.1;
    double rate = 0.1;
};

struct GpConfig {
    double default_fitness = 1.0;
    int population_size = 50;
    double expected_tree_size = 30.0;
    int max_init_depth = 6;
    int min_init_depth = 2;
    InitMethod init_method = InitMethod::Ptc1;
    // The depth PTC1's pseudocode gives the root: 0 as in thesis 6.3.4.4, so a
    // maximum depth of 6 allows 7 levels; 1 counts as Grow and Full do (a leaf = 1).
    int ptc1_root_depth = 0;
    tree::PrimitiveSetConfig primitives{
        {tree::Op::Add, tree::Op::Mul, tree::Op::Atan, tree::Op::Sin, tree::Op::Gauss},
        {1, 1, 1, 1, 1}, 4, {1.0, -1.0}};
    SelectionType selection = SelectionType::Tournament;
    int tournament_size = 5;
    bool lexicographic_parsimony = true;   // thesis key: tournamentSelection
    int trees_per_genotype = 1;            // numberOfTreesInForestGenotype
    bool prevent_duplicates = true;
    int duplicate_retries = 20;            // bounded retries before accepting a duplicate
    double crossover_rate = 0.9;
    double mutation_rate = 0.1;            // reproduction rate = 1 - crossover - mutation
    int elitism = 0;                       // the thesis copies no elite
    NodeSelection node_selection = NodeSelection::Koza;
    InitMethod mutation_generator = InitMethod::Grow;   // grows mutation's new subtrees
    int max_mutation_depth = 4;            // depth of subtrees grown by mutation
    int max_tree_depth = 17;               // per-tree cap without bloat control (Koza); 0 = none
    ForestDepth forest_depth = ForestDepth::Sum;
    DirectGenes direct;                    // none unless the experiment asks (Offset-HybrID)

    // Levels (a leaf = 1) of the deepest tree the initialisation can make, and of
    // the deepest forest: the "maximum allowed depth during initialization" that
    // bounds the heavy Dynamic Limit from below (thesis 5.2.2).
    int generated_tree_levels() const;
    int generated_forest_depth() const;
};

// A depth as the settings give it for `method`, in levels (a leaf = 1): PTC1
// with ptc1_root_depth 0 counts from the root's 0, so it allows one level more.
int levels(const GpConfig& cfg, InitMethod method, int depth);

struct BloatConfig {
    bool enabled = true;                   // useBloatControl
    BloatVariant variant = BloatVariant::Simple;
};

} // namespace cic::gp
