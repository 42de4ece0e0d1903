#include "cic/gp/evolution.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "cic/core/limits.hpp"
#include "cic/gp/operators.hpp"

namespace cic::gp {
namespace {

using Clock = std::chrono::steady_clock;

IndividualPtr make_child(EvolutionState& st, tree::Forest genotype, std::vector<std::uint64_t> parents,
                         std::vector<double> direct = {}) {
    auto c = std::make_shared<Individual>();
    c->id = st.next_id++;
    c->genotype = std::move(genotype);
    c->direct = std::move(direct);
    c->parents = std::move(parents);
    return c;
}

// A copy that stands in for a rejected child: same genotype and fitness, a new id.
IndividualPtr copy_of(EvolutionState& st, const Individual& parent) {
    auto c = std::make_shared<Individual>(parent);
    c->id = st.next_id++;
    c->parents = {parent.id};
    c->illegal = false;
    return c;
}


// Parents by id: an open-addressing table keyed by the id's low bits. Ids are
// handed out in sequence, so they spread evenly and a look-up is one probe or
// two. It pays: with a std::unordered_map a DEAP-symbreg run takes 6-8 % more
// CPU time (scripts/bench-gp-tricks.sh, 2026-12-01: 1.08x, Wilcoxon p < 0.001).
class ParentIndex {
public:
    // `slots` is storage kept by the caller, so that no generation allocates.
    ParentIndex(const Population& parents, std::vector<const Individual*>& slots) : slots_(slots) {
        std::size_t cap = 16;
        while (cap < 2 * parents.size()) cap *= 2;
        mask_ = cap - 1;
        slots_.assign(cap, nullptr);
        for (const auto& p : parents) {
            std::size_t k = p->id & mask_;
            while (slots_[k] && slots_[k]->id != p->id) k = (k + 1) & mask_;
            if (!slots_[k]) slots_[k] = p.get();   // the first of equal ids, as a map's emplace
        }
    }
    const Individual* find(std::uint64_t id) const {
        for (std::size_t k = id & mask_;; k = (k + 1) & mask_) {
            const Individual* p = slots_[k];
            if (!p || p->id == id) return p;
        }
    }
private:
    std::vector<const Individual*>& slots_;
    std::size_t mask_ = 0;
};

} // namespace

std::string to_string(StopReason r) {
    switch (r) {
    case StopReason::MaximumIterations: return "maximumIterations reached";
    case StopReason::MinimumFitness: return "minimumFitness reached";
    case StopReason::Interrupted: return "interrupted";
    case StopReason::HandedOver: return "handed over";
    }
    return "?";
}

GenerationRecord summarise(const Population& pop, const EvolutionState& st, ForestDepth measure) {
    GenerationRecord r;
    r.generation = pop.generation;
    r.limit = st.bloat.limit;
    r.evaluations = st.evaluations;
    if (pop.empty()) return r;
    thread_local std::vector<double> f;   // reused: no allocation per generation
    f.clear();
    f.reserve(pop.size());
    double sum_of_sums = 0, sum_of_maxes = 0, size_sum = 0;
    for (const auto& ind : pop) {
        f.push_back(ind->fitness);
        const int d_sum = ind->depth(ForestDepth::Sum), d_max = ind->depth(ForestDepth::Max);
        const std::size_t s = ind->size();
        sum_of_sums += d_sum;
        sum_of_maxes += d_max;
        size_sum += static_cast<double>(s);
        r.max_depth_sum = std::max(r.max_depth_sum, d_sum);
        r.max_depth_max = std::max(r.max_depth_max, d_max);
        r.max_size = std::max(r.max_size, s);
        if (ind->illegal) ++r.illegal;
    }
    const auto n = static_cast<double>(pop.size());
    r.mean = std::accumulate(f.begin(), f.end(), 0.0) / n;
    r.mean_depth_sum = sum_of_sums / n;
    r.mean_depth_max = sum_of_maxes / n;
    const bool by_sum = measure == ForestDepth::Sum;
    r.mean_depth = by_sum ? r.mean_depth_sum : r.mean_depth_max;
    r.max_depth = by_sum ? r.max_depth_sum : r.max_depth_max;
    r.mean_size = size_sum / n;
    const std::size_t m = f.size() / 2;
    if (std::any_of(f.begin(), f.end(), [](double v) { return std::isnan(v); })) {
        std::sort(f.begin(), f.end());   // as before: NaN has no place in a selection
        r.median = f.size() % 2 ? f[m] : 0.5 * (f[m - 1] + f[m]);
    } else {
        // The m-th smallest (and for an even count the largest below it): the sorted values.
        std::nth_element(f.begin(), f.begin() + static_cast<long>(m), f.end());
        r.median = f.size() % 2 ? f[m] : 0.5 * (*std::max_element(f.begin(), f.begin() + static_cast<long>(m)) + f[m]);
    }
    const Individual& best = pop.best();
    r.best = best.fitness;
    r.best_id = best.id;
    return r;
}

// ---------------------------------------------------------------- Initialise

Initialise::Initialise(const GpConfig& cfg, const tree::PrimitiveSet& ps)
    : cfg_(cfg),
      gen_(ps, cfg.init_method, cfg.expected_tree_size, levels(cfg, cfg.init_method, cfg.min_init_depth),
           cfg.generated_tree_levels()) {}

void Initialise::apply(Population& pop, EvolutionState& st) {
    pop.individuals.clear();
    pop.generation = 0;
    SeenGenotypes seen;
    const auto n = static_cast<std::size_t>(cfg_.population_size);
    for (std::size_t slot = 0; slot < n; ++slot) {
        tree::Forest f;
        std::vector<double> direct;
        for (int attempt = 0;; ++attempt) {
            f.clear();
            for (int t = 0; t < cfg_.trees_per_genotype; ++t) f.push_back(gen_.generate(st.rng, slot, n));
            if (cfg_.direct.count > 0) direct = initial_direct(st.rng, cfg_.direct);   // no draw without genes
            if (!cfg_.prevent_duplicates || seen.insert(f, direct)) break;
            if (attempt >= cfg_.duplicate_retries) break;   // bounded: accept a duplicate
        }
        auto ind = make_child(st, std::move(f), {}, std::move(direct));
        ind->fitness = cfg_.default_fitness;
        pop.individuals.push_back(std::move(ind));
    }
}

// ------------------------------------------------------------------ Evaluate

void Evaluate::apply(Population& pop, EvolutionState& st) {
    auto& todo = todo_;   // a member, so its capacity is reused every generation
    todo.clear();
    for (const auto& ind : pop)
        if (!ind->evaluated) todo.push_back(ind);
    if (todo.empty()) return;
    eval_.evaluate(todo);
    for (const auto& ind : todo) {
        if (!ind->evaluated) {
            todo.clear();
            throw std::logic_error("evaluator left an individual unevaluated");
        }
        if (ind->failed) ++failed_;
    }
    st.evaluations += static_cast<long>(todo.size());
    todo.clear();   // holds no individual between calls
}

// --------------------------------------------------------------------- Breed

Breed::Breed(const GpConfig& cfg, const tree::PrimitiveSet& ps)
    : cfg_(cfg),
      mutation_levels_(levels(cfg, cfg.mutation_generator, cfg.max_mutation_depth)),
      gen_(ps, cfg.mutation_generator, cfg.expected_tree_size, 1, mutation_levels_) {}

std::vector<IndividualPtr> Breed::breed_event(EvolutionState& st, SeenGenotypes& seen,
                                              std::size_t room) {
    const std::span<const IndividualPtr> parents(parents_.individuals);
    std::vector<IndividualPtr> out;
    out.reserve(2);
    // One breeding event, retried while it only yields duplicates (bounded).
    for (int attempt = 0; out.empty(); ++attempt) {
        const bool force = attempt >= cfg_.duplicate_retries;
        // Hashes are needed only to prevent duplicates (`seen` is not read otherwise).
        // A child inherits the direct genes of its first parent (whose root its
        // trees keep), moved by a Gaussian step (GpConfig::direct).
        auto genes_of = [&](const Individual& p) {
            return cfg_.direct.count > 0 ? mutate_direct(st.rng, p.direct, cfg_.direct) : std::vector<double>{};
        };
        auto admit = [&](tree::Forest f, std::vector<double> direct, std::vector<std::uint64_t> ids,
                         const Individual& a, const Individual* b) {
            if (out.size() >= room) return;
            if (cfg_.prevent_duplicates && !seen.insert(f, direct) && !force) return;
            // Evaluation is a pure function of the genotype: a child identical to a
            // parent (e.g. crossover swapping equal subtrees) inherits its fitness
            // instead of being evaluated again. About a third of children in
            // symbolic regression; results are the same, only faster.
            const Individual* same = f == a.genotype && direct == a.direct ? &a
                : (b && f == b->genotype && direct == b->direct ? b : nullptr);
            auto child = make_child(st, std::move(f), std::move(ids), std::move(direct));
            if (same && same->evaluated) {
                child->fitness = same->fitness;
                child->evaluated = true;
                child->failed = same->failed;
                child->failure = same->failure;
            }
            out.push_back(std::move(child));
        };
        const double r = st.rng.uniform();
        const Individual& p1 = *parents[select(st.rng, parents, cfg_)];
        if (r < cfg_.crossover_rate) {
            const Individual& p2 = *parents[select(st.rng, parents, cfg_)];
            auto [a, b] = crossover(st.rng, p1.genotype, p2.genotype, cfg_.node_selection);
            auto genes_a = genes_of(p1);
            auto genes_b = genes_of(p2);
            admit(std::move(a), std::move(genes_a), {p1.id, p2.id}, p1, &p2);
            admit(std::move(b), std::move(genes_b), {p2.id, p1.id}, p2, &p1);
        } else if (r < cfg_.crossover_rate + cfg_.mutation_rate) {
            auto trees = mutate(st.rng, p1.genotype, gen_, mutation_levels_, cfg_.node_selection);
            admit(std::move(trees), genes_of(p1), {p1.id}, p1, nullptr);
        } else {
            // Reproduction: an unchanged copy keeps its known fitness.
            if (cfg_.prevent_duplicates && !seen.insert(p1.genotype, p1.direct) && !force) continue;
            out.push_back(copy_of(st, p1));
        }
    }
    return out;
}

void Breed::apply(Population& pop, EvolutionState& st) {
    // The generation bred from last time is released one individual per child
    // below rather than all at once: each free is then followed by allocations of
    // the same sizes, which malloc serves from its per-thread cache (a bulk free of
    // hundreds of genotypes overflows that cache and makes every later allocation
    // take the slow path). Only the order in which memory is freed changes. It
    // pays: freeing the generation at once costs a DEAP-symbreg run 4-10 % more
    // CPU time (scripts/bench-gp-tricks.sh, 2026-12-01: 1.04x-1.10x, p < 0.01).
    retiring_ = std::move(parents_.individuals);
    std::reverse(retiring_.begin(), retiring_.end());   // released from the back: first-born first
    parents_ = std::move(pop);   // pop is replaced below; nothing reads it meanwhile
    const auto n = static_cast<std::size_t>(cfg_.population_size);
    Population next;
    next.individuals.reserve(n);
    next.generation = parents_.generation + 1;
    SeenGenotypes seen;

    // Elitism: the best survive unchanged (shared, already evaluated). `better`
    // is a strict total order, so a partial sort picks the same elites as a full one.
    auto& ranked = ranked_;   // pointers into parents_, storage reused across generations
    ranked.clear();
    for (const auto& p : parents_.individuals) ranked.push_back(&p);
    const std::size_t elites = std::min(static_cast<std::size_t>(std::max(0, cfg_.elitism)), ranked.size());
    std::partial_sort(ranked.begin(), ranked.begin() + static_cast<long>(elites), ranked.end(),
                      [](const IndividualPtr* a, const IndividualPtr* b) { return better(**a, **b); });
    for (std::size_t e = 0; e < elites; ++e) {
        next.individuals.push_back(*ranked[e]);
        if (cfg_.prevent_duplicates) seen.insert((*ranked[e])->genotype, (*ranked[e])->direct);
    }
    while (next.size() < n) {
        if (!retiring_.empty()) retiring_.pop_back();   // room for this event's first child
        for (auto& c : breed_event(st, seen, n - next.size())) next.individuals.push_back(std::move(c));
        if (!retiring_.empty()) retiring_.pop_back();   // and for the next event's allocations
    }
    retiring_.clear();
    pop = std::move(next);
}

std::vector<std::size_t> Breed::replace_duplicates(Population& pop, EvolutionState& st) {
    std::vector<std::size_t> slots;
    if (!cfg_.prevent_duplicates) return slots;
    SeenGenotypes seen;
    for (std::size_t i = 0; i < pop.size(); ++i)
        if (!seen.insert(pop[i].genotype, pop[i].direct)) slots.push_back(i);
    for (auto i : slots) pop.individuals[i] = breed_event(st, seen, 1).front();
    return slots;
}

// -------------------------------------------------------------- BloatControl

BloatControl::BloatControl(const GpConfig& gp, const BloatConfig& cfg, const Breed& breed)
    : gp_(gp), cfg_(cfg), breed_(breed) {}

DynamicLimits BloatControl::limits() const {
    return DynamicLimits(cfg_.variant, gp_.generated_forest_depth(), gp_.forest_depth);
}

void BloatControl::initialise(const Population& evaluated, EvolutionState& st) {
    if (!cfg_.enabled) return;
    DynamicLimits dl = limits();
    dl.initialise(evaluated);
    st.bloat = dl.state();
}

void BloatControl::filter(Population& pop, EvolutionState& st, std::span<const std::size_t> slots) {
    const ParentIndex by_id(breed_.parents(), index_);
    auto find = [&by_id](std::uint64_t id) { return by_id.find(id); };

    std::optional<DynamicLimits> dl;
    if (cfg_.enabled) {
        dl.emplace(limits());
        dl->set_state(st.bloat);
    }
    for (const std::size_t i : slots) {
        auto& ind = pop.individuals[i];
        if (ind->parents.empty()) continue;
        const Individual* p1 = find(ind->parents[0]);
        if (!p1) continue;   // an elite carried over
        if (ind->parents.size() == 1 && ind->genotype == p1->genotype) continue;  // a copy (or its genes moved)
        const Individual* p2 = ind->parents.size() > 1 ? find(ind->parents[1]) : nullptr;
        // No tree past the size limit (core/limits.hpp), whatever the bloat control;
        // then Dynamic Limits, or else Koza's per-tree cap (maximumTreeDepth 0 = none).
        const bool fits = std::all_of(ind->genotype.begin(), ind->genotype.end(),
                                      [](const tree::Tree& t) { return t.size() <= limits::kMaxTreeNodes; });
        const bool ok = fits && (dl ? dl->accept(*ind, *p1, p2)
                                    : gp_.max_tree_depth == 0 || ind->depth(ForestDepth::Max) <= gp_.max_tree_depth);
        if (!ok) ind = copy_of(st, *p1);
    }
    if (dl) st.bloat = dl->state();
}

void BloatControl::end_generation(Population& pop, EvolutionState& st) {
    if (!cfg_.enabled) return;
    DynamicLimits dl = limits();
    dl.set_state(st.bloat);
    dl.end_generation(pop);
    st.bloat = dl.state();
}

void BloatControl::restart_best(const Population& evaluated, EvolutionState& st) const {
    if (!cfg_.enabled) return;
    st.bloat.best_fitness = evaluated.best().fitness;
}

// -------------------------------------------------------------------- evolve

Generations::Generations(const GpConfig& gp, const BloatConfig& bloat, const tree::PrimitiveSet& ps,
                         Evaluator& evaluator, EvolutionState state, std::optional<Population> start)
    : gp_(gp), init_(gp, ps), evaluate_(evaluator), breed_(gp, ps), control_(gp, bloat, breed_),
      state_(std::move(state)) {
    if (start) {
        pop_ = std::move(*start);
        evaluate_.apply(pop_, state_);   // no-op for a saved, evaluated population
    } else {
        init_.apply(pop_, state_);
        evaluate_.apply(pop_, state_);
        control_.initialise(pop_, state_);
        control_.end_generation(pop_, state_);
    }
}

GenerationRecord Generations::record(int max_generations) {
    GenerationRecord rec = summarise(pop_, state_, gp_.forest_depth);
    rec.max_generations = max_generations;
    rec.failed = evaluate_.take_failed();
    rec.wall_seconds = std::chrono::duration<double>(Clock::now() - session_start_).count();
    rec.generation_seconds = std::chrono::duration<double>(Clock::now() - gen_start_).count();
    return rec;
}

void Generations::step() {
    gen_start_ = Clock::now();
    breed_.apply(pop_, state_);
    evaluate_.apply(pop_, state_);
    all_.resize(pop_.size());
    std::iota(all_.begin(), all_.end(), std::size_t{0});
    control_.filter(pop_, state_, all_);
    // Rejected children became parent copies: breed again where that left duplicates.
    for (int round = 0; round < gp_.duplicate_retries; ++round) {
        const auto slots = breed_.replace_duplicates(pop_, state_);
        if (slots.empty()) break;
        evaluate_.apply(pop_, state_);
        control_.filter(pop_, state_, slots);
    }
    control_.end_generation(pop_, state_);
}

void Generations::reevaluate() {
    gen_start_ = Clock::now();
    for (auto& ind : pop_.individuals) {   // fresh copies: a pointer may be shared with the bred-from generation
        auto again = std::make_shared<Individual>(*ind);
        again->evaluated = false;
        ind = std::move(again);
    }
    ++pop_.generation;
    evaluate_.apply(pop_, state_);
    control_.restart_best(pop_, state_);
    control_.end_generation(pop_, state_);
}

EvolutionResult Generations::finish(StopReason reason) {
    EvolutionResult result;
    result.population = std::move(pop_);
    result.state = std::move(state_);
    result.reason = reason;
    return result;
}

EvolutionResult evolve(const GpConfig& gp, const BloatConfig& bloat, const StopConditions& stop,
                       const tree::PrimitiveSet& ps, Evaluator& evaluator, EvolutionState state,
                       std::optional<Population> start, const EvolutionHooks& hooks) {
    if (stop.maximum_iterations < 1) throw std::invalid_argument("maximumIterations must be >= 1");
    const bool resumed = start.has_value();
    Generations g(gp, bloat, ps, evaluator, std::move(state), std::move(start));
    GenerationRecord rec = g.record(stop.maximum_iterations);
    if (!resumed && hooks.on_generation) hooks.on_generation(rec);
    for (bool first = true;; first = false) {
        StopReason reason{};
        bool done = true;
        if (rec.best >= stop.minimum_fitness) reason = StopReason::MinimumFitness;
        else if (hooks.hand_over && hooks.hand_over(rec)) reason = StopReason::HandedOver;
        else if (g.population().generation + 1 >= stop.maximum_iterations) reason = StopReason::MaximumIterations;
        else if (hooks.stop_requested && hooks.stop_requested->load()) reason = StopReason::Interrupted;
        else done = false;
        // A resumed population was saved already; save it again only if it is also the last.
        const bool fresh = !(first && resumed);
        if (hooks.on_checkpoint && (fresh || done)) hooks.on_checkpoint(g.population(), g.state(), done);
        if (done) return g.finish(reason);
        g.step();
        rec = g.record(stop.maximum_iterations);
        if (hooks.on_generation) hooks.on_generation(rec);
    }
}

} // namespace cic::gp
