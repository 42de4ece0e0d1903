#pragma once
// MAP-Elites over parameter vectors in the unit box (the gait experiment's
// encoding): Mouret & Clune 2015, with the Gaussian variation of Vassiliades &
// Mouret 2018 left out (plain isotropic Gaussian mutation, clamped to [0, 1]).
// The first batches sample the box uniformly until `initial` solutions have
// been evaluated; every later batch mutates elites drawn uniformly from the
// archive. Batches are evaluated together (worker processes, MPI ranks) and
// offered to the archive in batch order, so a run is the same for any number of
// workers. Deterministic from its seed; its state saves and restores exactly.
#include <cstdint>
#include <functional>
#include <vector>

#include "cic/core/rng.hpp"
#include "cic/gp/grid_archive.hpp"

namespace cic::gp {

struct VectorMapElitesConfig {
    GridSpec grid;
    std::size_t dimension = 0;   // parameters per solution
    int batch = 100;             // solutions evaluated together
    int initial = 100;           // uniform random solutions before any mutation
    double sigma = 0.1;          // the mutation's standard deviation, in the unit box

    // Throws std::invalid_argument naming the field.
    void validate() const;
};

// What an evaluation gives back. A failed evaluation is counted, not archived.
struct Evaluation {
    double fitness = 0;
    std::vector<double> descriptor;
    bool failed = false;
};
using VectorBatch = std::function<std::vector<Evaluation>(const std::vector<std::vector<double>>&)>;

class VectorMapElites {
public:
    using Archive = GridArchive<std::vector<double>>;

    VectorMapElites(VectorMapElitesConfig config, std::uint64_t seed);

    // Evaluates one batch (the last may be smaller: at most `budget_left`) and
    // offers it to the archive; returns how many solutions were kept.
    int step(const VectorBatch& evaluate, long budget_left);

    const VectorMapElitesConfig& config() const { return config_; }
    const Archive& archive() const { return archive_; }
    long evaluations() const { return evaluations_; }
    long failed() const { return failed_; }
    int batches() const { return batches_; }
    const Rng& rng() const { return rng_; }

    // A checkpoint's state: the archive's elites, the counters and the RNG.
    void restore(const std::map<std::size_t, Archive::Elite>& elites, long evaluations, long failed, int batches,
                 const Rng::State& rng);

private:
    std::vector<double> random_point();
    std::vector<double> mutant();

    VectorMapElitesConfig config_;
    Archive archive_;
    Rng rng_;
    long evaluations_ = 0;
    long failed_ = 0;
    int batches_ = 0;
};

} // namespace cic::gp
