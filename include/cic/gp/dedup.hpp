#pragma once
// preventDuplicates (thesis Table B.1): the genotypes already in the generation
// being built, kept as structural hashes. This is the one duplicate check of
// the GP loop (initialisation, breeding, re-breeding after bloat control).
#include <cstdint>
#include <span>
#include <unordered_set>

#include "cic/tree/tree.hpp"

namespace cic::gp {

// The structural hash of a genotype: tree::hash of the trees, and when the
// genotype has direct genes (GpConfig::direct) their bits mixed in, so two
// genotypes that differ only in a gene differ in hash. Without genes it is
// tree::hash(trees), the hash of every file written before the genes existed.
std::uint64_t genotype_hash(const tree::Forest& trees, std::span<const double> direct = {});

// Genotypes compare by 64-bit structural hash (tree::hash). Two different
// genotypes with one hash would count as duplicates: the odds are about
// n^2 / 2^65 per generation, and the cost would be one more breeding retry,
// never a wrong fitness.
class SeenGenotypes {
public:
    // True if f's hash was new (and is now recorded).
    bool insert(const tree::Forest& f, std::span<const double> direct = {}) {
        return hashes_.insert(genotype_hash(f, direct)).second;
    }
    bool contains(const tree::Forest& f, std::span<const double> direct = {}) const {
        return hashes_.count(genotype_hash(f, direct)) != 0;
    }
    std::size_t size() const { return hashes_.size(); }
    void clear() { hashes_.clear(); }

private:
    std::unordered_set<std::uint64_t> hashes_;
};

} // namespace cic::gp
