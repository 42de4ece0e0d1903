#pragma once
// Variation and selection (thesis 5.1.2-5.1.4, 7.3.1). Forest operators apply
// the tree operator tree by tree.
#include <span>
#include <utility>
#include <vector>

#include "cic/core/rng.hpp"
#include "cic/gp/config.hpp"
#include "cic/gp/generators.hpp"
#include "cic/gp/individual.hpp"

namespace cic::gp {

// Picks a node. Koza: a function node with probability 0.9 when the tree has
// any, else a leaf, each uniformly among its kind. Uniform: any node alike.
std::size_t pick_node(Rng& rng, const tree::Tree& t, NodeSelection how = NodeSelection::Koza);

// Subtree mutation: a picked node is replaced by a new subtree of at most
// max_sub_depth levels, made by gen's method (TreeGenerator::subtree).
tree::Tree mutate(Rng& rng, const tree::Tree& t, const TreeGenerator& gen, int max_sub_depth,
                  NodeSelection how = NodeSelection::Koza);
tree::Forest mutate(Rng& rng, const tree::Forest& f, const TreeGenerator& gen, int max_sub_depth,
                    NodeSelection how = NodeSelection::Koza);

// Direct genes (GpConfig::direct): `count` draws of N(0, sigma) clamped to
// [-limit, limit], and the Gaussian step that moves each gene with probability
// `rate`. Both throw std::invalid_argument for sigma < 0, limit <= 0, a rate
// outside [0, 1] or a non-finite value; mutate_direct also for genes of
// another count. count 0 draws nothing.
std::vector<double> initial_direct(Rng& rng, const DirectGenes& cfg);
std::vector<double> mutate_direct(Rng& rng, std::vector<double> genes, const DirectGenes& cfg);

// One-point subtree crossover: swaps picked subtrees; returns both children.
std::pair<tree::Tree, tree::Tree> crossover(Rng& rng, const tree::Tree& a, const tree::Tree& b,
                                            NodeSelection how = NodeSelection::Koza);
std::pair<tree::Forest, tree::Forest> crossover(Rng& rng, const tree::Forest& a, const tree::Forest& b,
                                                NodeSelection how = NodeSelection::Koza);

// Tournament of k with lexicographic parsimony (on equal fitness the smaller
// genotype wins). Returns an index into pop. Throws on k < 1 or empty pop.
std::size_t tournament(Rng& rng, std::span<const IndividualPtr> pop, int k, bool parsimony);
// Roulette wheel. Fitness is shifted by (1e-12 - min fitness) when any is <= 0,
// so the worst keeps a tiny chance and negative fitness works (documented).
std::size_t roulette(Rng& rng, std::span<const IndividualPtr> pop);
std::size_t select(Rng& rng, std::span<const IndividualPtr> pop, const GpConfig& cfg);

} // namespace cic::gp
