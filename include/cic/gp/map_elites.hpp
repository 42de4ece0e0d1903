#pragma once
// The MAP-Elites loop (Mouret & Clune 2015, "Illuminating search spaces by
// mapping elites"), generic over the solution: a HyperGP genotype
// (forest_map_elites.hpp) or a gait's parameter vector (vector_map_elites.hpp).
// The variation is a block the caller plugs in (an Emitter, as pyribs calls
// it): how to make a solution from nothing, and how to make one from the
// archive. The first batches are made from nothing until `initial` solutions
// have been evaluated (or while every one so far failed); every later batch
// varies elites. A batch is evaluated together (worker processes, MPI ranks)
// and offered to the archive in batch order, so a run is the same for any
// number of workers. Deterministic from its seed; its state (archive, counters,
// RNG) saves and restores exactly.
#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cic/core/rng.hpp"
#include "cic/gp/grid_archive.hpp"

namespace cic::gp {

// What an evaluation gives back. A failed evaluation is counted, not archived.
struct Evaluation {
    double fitness = 0;
    std::vector<double> descriptor;
    bool failed = false;
};

struct MapElitesConfig {
    GridSpec grid;
    int batch = 100;      // solutions evaluated together
    int initial = 100;    // solutions made from nothing before any variation

    // Throws std::invalid_argument naming the field.
    void validate() const;
};

// What became of one solution of a batch, as an emitter that learns is told.
struct Outcome {
    enum class Kind { NewCell, Improved, NotKept, Failed };
    Kind kind = Kind::Failed;
    double fitness = 0;
    double improvement = 0;   // fitness minus the cell's elite before (NewCell: the fitness itself)
};

template <class Solution>
struct Emitter {
    std::function<Solution(Rng&)> random;
    // One solution from the archive (never empty here). An emitter that makes
    // whole batches gives `ask` instead.
    std::function<Solution(Rng&, const GridArchive<Solution>&)> vary;
    // Optional: throws std::invalid_argument for a restored elite this run
    // could not have made (a parameter vector of another size).
    std::function<void(const Solution&)> check;
    // Optional, for an emitter that learns from the archive (CMA-ME): `ask`
    // makes the varied part of a batch at once, `tell` then hears what became
    // of each of them, in the same order, and `save` / `load` carry its state
    // through a checkpoint (load gets what save gave; "" for a fresh emitter).
    std::function<std::vector<Solution>(Rng&, const GridArchive<Solution>&, std::size_t count)> ask;
    std::function<void(const std::vector<Outcome>&)> tell;
    std::function<std::string()> save;
    std::function<void(const std::string&)> load;
};

template <class Solution>
class MapElites {
public:
    using Archive = GridArchive<Solution>;
    using Batch = std::function<std::vector<Evaluation>(const std::vector<Solution>&)>;

    MapElites(MapElitesConfig config, Emitter<Solution> emitter, std::uint64_t seed)
        : config_((config.validate(), std::move(config))), emitter_(std::move(emitter)), archive_(config_.grid),
          rng_(seed) {
        if (!emitter_.random || (!emitter_.vary && !emitter_.ask) || bool(emitter_.ask) != bool(emitter_.tell) ||
            bool(emitter_.save) != bool(emitter_.load))
            throw std::invalid_argument("map-elites: the emitter is incomplete");
    }

    // Makes one batch (the last may be smaller: at most `budget_left`),
    // evaluates it and offers it to the archive; returns how many were kept.
    int step(const Batch& evaluate, long budget_left) {
        if (budget_left < 1) throw std::invalid_argument("map-elites: no evaluation left in the budget");
        const long size = std::min<long>(config_.batch, budget_left);
        std::vector<Solution> batch;
        batch.reserve(static_cast<std::size_t>(size));
        long fresh = 0;   // made from nothing: the first ones of the batch
        while (fresh < size && (evaluations_ + fresh < config_.initial || archive_.empty())) {
            batch.push_back(emitter_.random(rng_));
            ++fresh;
        }
        if (emitter_.ask && fresh < size) {
            std::vector<Solution> asked = emitter_.ask(rng_, archive_, static_cast<std::size_t>(size - fresh));
            if (asked.size() != static_cast<std::size_t>(size - fresh))
                throw std::logic_error("map-elites: the emitter made " + std::to_string(asked.size()) + " of " +
                                       std::to_string(size - fresh) + " solutions");
            for (auto& a : asked) batch.push_back(std::move(a));
        } else {
            for (long i = fresh; i < size; ++i) batch.push_back(emitter_.vary(rng_, archive_));
        }
        const std::vector<Evaluation> results = evaluate(batch);
        if (results.size() != batch.size())
            throw std::logic_error("map-elites: " + std::to_string(results.size()) + " results for a batch of " +
                                   std::to_string(batch.size()));
        int kept = 0;
        std::vector<Outcome> outcomes;
        for (std::size_t i = 0; i < batch.size(); ++i) {
            Outcome o;
            if (results[i].failed) {
                ++failed_;
            } else {
                const auto* before = archive_.at(archive_.cell_of(results[i].descriptor));
                o.fitness = results[i].fitness;
                o.improvement = before ? results[i].fitness - before->fitness : results[i].fitness;
                const bool taken = archive_.offer(results[i].descriptor, results[i].fitness, std::move(batch[i]));
                o.kind = !taken ? Outcome::Kind::NotKept : before ? Outcome::Kind::Improved : Outcome::Kind::NewCell;
                kept += taken;
            }
            if (i >= static_cast<std::size_t>(fresh)) outcomes.push_back(o);
        }
        if (emitter_.tell && !outcomes.empty()) emitter_.tell(outcomes);
        evaluations_ += size;
        ++batches_;
        return kept;
    }

    const MapElitesConfig& config() const { return config_; }
    const Archive& archive() const { return archive_; }
    long evaluations() const { return evaluations_; }
    long failed() const { return failed_; }
    int batches() const { return batches_; }
    const Rng& rng() const { return rng_; }

    // The emitter's own state for a checkpoint ("" when it keeps none).
    std::string emitter_state() const { return emitter_.save ? emitter_.save() : std::string(); }

    // A checkpoint's state: the archive's elites, the counters, the RNG and
    // the emitter's state (refused by an emitter that keeps none).
    void restore(const std::map<std::size_t, typename Archive::Elite>& elites, long evaluations, long failed,
                 int batches, const Rng::State& rng, const std::string& emitter_state = {}) {
        if (!emitter_state.empty() && !emitter_.load)
            throw std::invalid_argument("map-elites: an emitter state for an emitter that keeps none");
        if (evaluations < 0 || failed < 0 || failed > evaluations || batches < 0)
            throw std::invalid_argument("map-elites: counters out of range");
        Archive archive(config_.grid);
        for (const auto& [cell, e] : elites) {
            if (emitter_.check) emitter_.check(e.solution);
            archive.restore(cell, e);
        }
        if (emitter_.load) emitter_.load(emitter_state);
        archive_ = std::move(archive);
        evaluations_ = evaluations;
        failed_ = failed;
        batches_ = batches;
        rng_.set_state(rng);
    }

private:
    MapElitesConfig config_;
    Emitter<Solution> emitter_;
    Archive archive_;
    Rng rng_;
    long evaluations_ = 0;
    long failed_ = 0;
    int batches_ = 0;
};

} // namespace cic::gp
