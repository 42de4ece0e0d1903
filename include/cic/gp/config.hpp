#pragma once
// Plain settings of the GP engine, with the thesis's defaults (Appendix B).
// Validation happens once, at the boundary (io/settings).
#include <string>
#include <vector>

#include "cic/tree/primitives.hpp"

namespace cic::gp {

enum class InitMethod { Ptc1, Grow, Full, RampedHalfAndHalf };
enum class SelectionType { Tournament = 0, Roulette = 1 };
enum class BloatVariant { Simple = 0, Heavy = 1, VeryHeavy = 2 };

struct GpConfig {
    double default_fitness = 1.0;
    int population_size = 50;
    double expected_tree_size = 30.0;
    int max_init_depth = 6;
    int min_init_depth = 2;
    InitMethod init_method = InitMethod::Ptc1;
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
    int elitism = 1;
    int max_mutation_depth = 4;            // depth of subtrees grown by mutation
    int max_tree_depth = 17;               // hard cap when bloat control is off (Koza)
};

struct BloatConfig {
    bool enabled = true;                   // useBloatControl
    BloatVariant variant = BloatVariant::Simple;
};

} // namespace cic::gp
