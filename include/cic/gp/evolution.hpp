#pragma once
// The generational loop (thesis fig. 5.2): initialise | load -> evaluate ->
// [statistics -> checkpoint -> breed -> evaluate -> bloat control]*. The thesis
// draws it as a pipeline of population modifiers (6.1); here the stages are
// plain classes that evolve() calls in order, because they do not share one
// signature: bloat control filters chosen slots against the bred-from
// generation, and duplicates are re-bred slot by slot. It knows no XML, ODE or
// CLI: experiments plug in an Evaluator, and observers receive a typed record
// per generation.
#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "cic/core/rng.hpp"
#include "cic/gp/bloat.hpp"
#include "cic/gp/config.hpp"
#include "cic/gp/dedup.hpp"
#include "cic/gp/generators.hpp"
#include "cic/gp/individual.hpp"

namespace cic::gp {

// Gives every individual in `todo` a fitness (and sets evaluated = true). Must be
// a pure function of each genotype, so results do not depend on order or workers.
class Evaluator {
public:
    virtual ~Evaluator() = default;
    virtual void evaluate(std::span<const IndividualPtr> todo) = 0;
};

// Everything that, with the population, fixes the rest of a run. Saved in every
// population file so that a resume continues bit for bit.
struct EvolutionState {
    Rng rng;
    std::uint64_t seed = 1;
    std::uint64_t next_id = 1;
    long evaluations = 0;
    BloatState bloat;
};

// One line of stats.csv and of the progress display.
struct GenerationRecord {
    int generation = 0;
    int max_generations = 0;
    double best = 0, mean = 0, median = 0;
    double mean_depth = 0;          // depth as GP.forestDepth measures it (what the limit bounds)
    int max_depth = 0;
    double mean_depth_sum = 0;      // both measures, whichever is configured (thesis fig. 7.4b: sum)
    int max_depth_sum = 0;
    double mean_depth_max = 0;
    int max_depth_max = 0;
    double mean_size = 0;
    std::size_t max_size = 0;
    int limit = 0;                  // dynamic depth limit (0 when bloat control is off)
    int illegal = 0;
    long evaluations = 0;           // cumulative
    int failed = 0;                 // evaluations of this generation that failed (physics, worker)
    double wall_seconds = 0;        // since this session started
    double generation_seconds = 0;  // this generation alone
    std::uint64_t best_id = 0;
};

GenerationRecord summarise(const Population& pop, const EvolutionState& st, ForestDepth measure);

struct StopConditions {
    int maximum_iterations = 50;    // generations evaluated, counting generation 0
    double minimum_fitness = 50.0;  // stop once the best reaches this
};

// Random initial population (the configured generator), unique if asked.
class Initialise {
public:
    Initialise(const GpConfig& cfg, const tree::PrimitiveSet& ps);
    void apply(Population& pop, EvolutionState& st);
private:
    const GpConfig& cfg_;
    TreeGenerator gen_;
};

// Evaluates every individual not yet evaluated.
class Evaluate {
public:
    explicit Evaluate(Evaluator& e) : eval_(e) {}
    void apply(Population& pop, EvolutionState& st);
    // Evaluations marked "failed" since the last call.
    int take_failed() { return std::exchange(failed_, 0); }
private:
    Evaluator& eval_;
    std::vector<IndividualPtr> todo_;   // scratch, empty between calls
    int failed_ = 0;
};

// Builds the next generation: elitism, then selection + crossover / mutation /
// reproduction; children carry their parents' ids. Children are not evaluated.
class Breed {
public:
    Breed(const GpConfig& cfg, const tree::PrimitiveSet& ps);
    void apply(Population& pop, EvolutionState& st);
    // The population bred from (for the bloat filter's parent look-up).
    const Population& parents() const { return parents_; }
    // preventDuplicates after bloat control: breeds again into every slot that
    // repeats an earlier genotype. Returns the slots refilled (not yet evaluated).
    std::vector<std::size_t> replace_duplicates(Population& pop, EvolutionState& st);
private:
    std::vector<IndividualPtr> breed_event(EvolutionState& st, SeenGenotypes& seen,
                                           std::size_t room);
    const GpConfig& cfg_;
    int mutation_levels_;   // maximumMutationDepth in levels (see gp::levels)
    TreeGenerator gen_;
    Population parents_;
    std::vector<const IndividualPtr*> ranked_;   // scratch for elitism
    std::vector<IndividualPtr> retiring_;        // scratch: the previous parents, freed while breeding
};

// Dynamic Limits filter over freshly evaluated children (thesis 5.2): a child
// that breaks its limit without beating the best is replaced by a copy of its
// first parent. Without bloat control it keeps the per-tree depth cap instead.
class BloatControl {
public:
    BloatControl(const GpConfig& gp, const BloatConfig& cfg, const Breed& breed);
    void initialise(const Population& evaluated, EvolutionState& st);
    // Checks the children in `slots`; a rejected one becomes a copy of its first parent.
    void filter(Population& pop, EvolutionState& st, std::span<const std::size_t> slots);
    // Heavy variants may lower the limit; marks individuals over it illegal.
    void end_generation(Population& pop, EvolutionState& st);
    // The problem changed (Generations::reevaluate): the best so far is the
    // re-evaluated population's best, since older fitness is not comparable;
    // the limit stays.
    void restart_best(const Population& evaluated, EvolutionState& st) const;
private:
    const GpConfig& gp_;
    const BloatConfig& cfg_;
    const Breed& breed_;
    std::vector<const Individual*> index_;   // scratch: parents by id (see filter)
    DynamicLimits limits() const;            // with the configured variant and measure
};

struct EvolutionHooks {
    std::function<void(const GenerationRecord&)> on_generation;
    // Called after each generation's record; `last` is true for the final one.
    std::function<void(const Population&, const EvolutionState&, bool last)> on_checkpoint;
    const std::atomic<bool>* stop_requested = nullptr;   // e.g. set by SIGINT
    // Asked after each generation's record (after on_generation): true ends the
    // loop there, as the last generation of this search, which a later phase
    // of the run continues (Switch-HybrID). Empty: never.
    std::function<bool(const GenerationRecord&)> hand_over;
};

enum class StopReason { MaximumIterations, MinimumFitness, Interrupted, HandedOver };
std::string to_string(StopReason r);

struct EvolutionResult {
    Population population;
    EvolutionState state;
    StopReason reason = StopReason::MaximumIterations;
};

// The loop of evolve(), one generation at a time, for a caller that owns the
// loop (the run's one loop, search/generational.cpp). Constructing it
// initialises and evaluates generation 0, or takes a loaded population (with
// its state) as it is; step() breeds, evaluates and filters the next one.
class Generations {
public:
    Generations(const GpConfig& gp, const BloatConfig& bloat, const tree::PrimitiveSet& ps, Evaluator& evaluator,
                EvolutionState state, std::optional<Population> start);
    Generations(const Generations&) = delete;
    Generations& operator=(const Generations&) = delete;

    // The current generation's record (its failed count taken: call once per generation).
    GenerationRecord record(int max_generations);
    void step();
    // Instead of a step, when the evaluator's problem has changed (a growing
    // robot's next body): the next generation is this population unchanged,
    // every individual evaluated again (counted in the evaluations), with
    // Dynamic Limits' best so far restarted from it. Uses no random numbers.
    void reevaluate();
    const Population& population() const { return pop_; }
    const EvolutionState& state() const { return state_; }
    // The population and state, moved out: the object is spent.
    EvolutionResult finish(StopReason reason);

private:
    using Clock = std::chrono::steady_clock;
    const GpConfig& gp_;
    Initialise init_;
    Evaluate evaluate_;
    Breed breed_;
    BloatControl control_;
    EvolutionState state_;
    Population pop_;
    Clock::time_point session_start_ = Clock::now(), gen_start_ = session_start_;
    std::vector<std::size_t> all_;   // every slot, for the bloat filter
};

// Runs the loop. If `start` is given (a loaded population, evaluated, with its
// state), it continues from there; otherwise it initialises and evaluates.
EvolutionResult evolve(const GpConfig& gp, const BloatConfig& bloat, const StopConditions& stop,
                       const tree::PrimitiveSet& ps, Evaluator& evaluator, EvolutionState state,
                       std::optional<Population> start, const EvolutionHooks& hooks);

} // namespace cic::gp
