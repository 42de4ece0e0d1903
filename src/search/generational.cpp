// The thesis's generational GP (fig. 5.2) as a search: PTC1 or ramped
// initialisation, tournament with parsimony, crossover and subtree mutation,
// Dynamic Limits (gp/evolution.hpp's Generations, one generation per step).
// Its checkpoint is the population file (io/population_xml.hpp), and its
// budget Control.maximumIterations. Any type whose genotypes are trees
// (symbolic regression, HyperGP and their registered types) runs with it.
#include "generational.hpp"

#include <limits>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cic/core/error.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/io/bodies.hpp"
#include "cic/io/checkpoint_origin.hpp"
#include "cic/io/experiment_types.hpp"
#include "cic/report/replay.hpp"
#include "cic/search/support.hpp"

namespace cic::search {
namespace {

// Offset-HybrID's offsets: a population holds as many per individual as the
// settings' robot has joints, in the substrate's range, or none without them.
void check_direct_offsets(const io::PopulationFile& loaded, const io::Settings& s, const std::string& file) {
    const gp::DirectGenes want =
        s.neural.direct_offsets ? hypergp::direct_offset_genes(hypergp::Model::from_settings(s)) : gp::DirectGenes{};
    if (loaded.offsets != want.count)
        throw InputError(fmt::format("population holds {} direct offsets per individual but the settings ask for {} "
                                     "(Neural.directOffsets = {}{}); use settings that match the population",
                                     loaded.offsets, want.count, s.neural.direct_offsets ? 1 : 0,
                                     s.neural.direct_offsets ? ", one per joint of the robot" : ""),
                         file);
    if (want.count > 0 && loaded.offset_limit != want.limit)
        throw InputError(fmt::format("population's offsets are in [-{0}, {0}] but this cic's are in [-{1}, {1}]",
                                     loaded.offset_limit, want.limit), file);
}

// A growing robot's checkpoint names its body (io/bodies.hpp): the one its
// generation is evaluated on under these settings.
void check_body(const io::PopulationFile& loaded, const io::Settings& s, const std::string& file) {
    if (!io::grows(s)) {
        if (loaded.body)
            throw InputError("population is of a growing robot (<body>), but these settings have one body "
                             "(Simulator.growRobotFiles is empty); use the settings it was made with", file);
        return;
    }
    const std::size_t want = io::body_of_generation(s, loaded.population.generation);
    if (!loaded.body || *loaded.body != want)
        throw InputError(fmt::format("population at generation {} is on body {}, but these settings' growing robot "
                                     "(Simulator.growRobotFiles, growAt) is on body {} there; use the settings it "
                                     "was made with",
                                     loaded.population.generation,
                                     loaded.body ? std::to_string(*loaded.body) : std::string("(none given)"), want),
                         file);
}

} // namespace

void PopulationCheckpoint::check_goes_on(const io::Settings& s) const {
    refuse_if_reached(population.population.best().fitness, s, file);
}

std::unique_ptr<PopulationCheckpoint> load_population_checkpoint(const io::Settings& s, const std::string& file) {
    auto c = std::make_unique<PopulationCheckpoint>();
    c->file = file;
    c->population = io::load_population(file);
    c->origin_note = io::check_origin(c->population.origin, s, file);
    c->settings_digest = c->population.settings_digest;
    c->generations = c->population.population.generation + 1;
    c->number = c->population.population.generation;
    c->evaluations = c->population.state.evaluations;
    io::check_compatible(c->population, s, file);
    check_direct_offsets(c->population, s, file);
    check_body(c->population, s, file);
    return c;
}

Generational::Generational(const Services& services, std::unique_ptr<PopulationCheckpoint> resume,
                           GenerationalHooks hooks)
    : services_(services), resume_(std::move(resume)), hooks_(std::move(hooks)), gp_(services.settings.gp),
      primitives_(services.settings.gp.primitives), header_(io::describe(services.settings)) {
    maximum_iterations_ = hooks_.hand_over ? std::numeric_limits<int>::max()   // the phase ends by hand_over
                                           : services.settings.control.maximum_iterations;
}

StatsLayout Generational::stats_layout() const {
    StatsLayout l;
    if (services_.continue_in_place && resume_) l.continue_after = resume_->population.population.generation;
    return l;
}

std::optional<Row> Generational::start() {
    const io::Settings& s = services_.settings;
    gp::EvolutionState state;
    state.seed = s.experiment.seed;
    state.rng = Rng(s.experiment.seed);
    std::optional<gp::Population> population;
    if (resume_) {
        say_checkpoint_notes(*resume_, services_);
        state = resume_->population.state;
        population = std::move(resume_->population.population);
        services_.say(fmt::format("resuming from {} at generation {} (seed {})", resume_->file,
                                  population->generation, state.seed));
    }
    const int workers = services_.context.workers;
    services_.say(fmt::format("cic {}: {} experiment, seed {}, {} worker{}, output {}", CIC_VERSION,
                              header_.experiment, state.seed, workers, workers == 1 ? "" : "s",
                              services_.run_dir.string()));
    experiment_ = experiments::make_experiment(services_.context);
    body_ = io::body_of_generation(s, population ? population->generation : 0);   // the checkpoint's, checked
    if (body_ != 0) experiment_->use_body(body_);
    gp_.direct = experiment_->direct_genes();   // Offset-HybrID's offsets, else none
    header_.offsets = gp_.direct.count;
    header_.offset_limit = gp_.direct.count > 0 ? gp_.direct.limit : 0.0;
    // What the evaluations column counts, where it is first seen.
    services_.log(fmt::format(
        "evaluations count every individual evaluated: a generation evaluates its new individuals only (elites and "
        "reproduced copies keep their fitness){}",
        s.bloat.enabled ? ", and under Dynamic Limits also each child bred past the depth limit, which is then "
                          "replaced by its parent unless it beats the best: so a generation may evaluate fewer or "
                          "more than its population"
                        : ""));
    const bool resumed = population.has_value();
    evaluations_before_ = state.evaluations;
    first_generation_ = resumed ? population->generation + 1 : 0;
    generations_ = std::make_unique<gp::Generations>(gp_, s.bloat, primitives_, experiment_->evaluator(),
                                                     std::move(state), std::move(population));
    record_ = generations_->record(maximum_iterations_);
    if (resumed) return std::nullopt;   // its record was written by the run it continues
    return row_of(record_);
}

Row Generational::row_of(const gp::GenerationRecord& r) {
    if (hooks_.on_generation) hooks_.on_generation(r);   // first: the checkpoint's annotation reads what it noted
    Row row;
    row.record = r;
    row.log = fmt::format("gen {} best {:.17g} mean {:.17g} median {:.17g} depth {:.3f}/{} size {:.2f}/{} limit {} "
                          "illegal {} evaluations {} {:.2f}s",
                          r.generation, r.best, r.mean, r.median, r.mean_depth, r.max_depth, r.mean_size, r.max_size,
                          r.limit, r.illegal, r.evaluations, r.wall_seconds);
    ProgressLine& p = row.progress;
    p.generation = r.generation;
    p.max_generations = hooks_.progress_generations > 0 ? hooks_.progress_generations : r.max_generations;
    p.evaluations_per_second = r.generation_seconds > 0
        ? static_cast<double>(r.evaluations - evaluations_before_) / r.generation_seconds : 0.0;
    evaluations_before_ = r.evaluations;
    p.best = r.best;
    p.mean = r.mean;
    p.limit = r.limit;
    const int done = r.generation + 1 - first_generation_;
    const int left = p.max_generations - (r.generation + 1);
    p.eta_seconds = done > 0 ? r.wall_seconds / done * left : -1.0;
    return row;
}

Stop Generational::stop(bool signal) {
    const io::Settings& s = services_.settings;
    bool done = true;
    if (record_.best >= s.control.minimum_fitness) reason_ = gp::StopReason::MinimumFitness;
    else if (hooks_.hand_over && hooks_.hand_over(record_)) reason_ = gp::StopReason::HandedOver;
    else if (generations_->population().generation + 1 >= maximum_iterations_) reason_ = gp::StopReason::MaximumIterations;
    else if (signal) reason_ = gp::StopReason::Interrupted;
    else done = false;
    if (!done) return {};
    return {gp::to_string(reason_), reason_ == gp::StopReason::Interrupted};
}

bool Generational::checkpoint_due(const Stop& stop) {
    // A resumed population was saved already; save it again only if it is also the last.
    const bool fresh = !(first_check_ && resume_);
    first_check_ = false;
    if (!fresh && !stop.done()) return false;
    const int interval = std::max(1, services_.settings.experiment.checkpoint_interval);
    // After every `interval` evaluated generations (generation g is the (g+1)-th).
    return stop.done() || (generations_->population().generation + 1) % interval == 0;
}

CheckpointText Generational::checkpoint() const {
    io::PopulationFile file = header_;
    file.population = generations_->population();
    file.state = generations_->state();
    if (io::grows(services_.settings)) file.body = body_;
    if (hooks_.annotate) hooks_.annotate(file);
    return {file.population.generation, io::to_xml(file)};
}

Row Generational::step() {
    // A growing robot moves to its next body at the generation its share of
    // the budget gives (io/bodies.hpp): that generation is the population
    // evaluated again there, no breeding, so the change costs one generation
    // of the budget and the stored fitness is always the current body's.
    const int next = generations_->population().generation + 1;
    if (const std::size_t body = io::body_of_generation(services_.settings, next); body != body_) {
        body_ = body;
        experiment_->use_body(body);
        const long before = generations_->state().evaluations;
        generations_->reevaluate();
        services_.say(fmt::format("generation {}: the robot grows to body {} ({}): the population is evaluated "
                                  "again there, {} evaluations",
                                  next, body, services_.settings.robot.grow_robot_files[body - 1],
                                  generations_->state().evaluations - before));
        record_ = generations_->record(maximum_iterations_);
        return row_of(record_);
    }
    generations_->step();
    record_ = generations_->record(maximum_iterations_);
    return row_of(record_);
}

std::string Generational::summary_text() const {
    const io::Settings& s = services_.settings;
    const gp::Population& pop = generations_->population();
    const gp::Individual& best = pop.best();
    std::string trees;
    for (const auto& t : best.genotype) trees += (trees.empty() ? "" : " | ") + t.to_string();
    std::string offsets;
    if (!best.direct.empty()) offsets = fmt::format("best direct offsets (x pi/2 rad): {:.4f}\n", fmt::join(best.direct, " "));
    return fmt::format("stopped: {} at generation {}\nbest: id {} fitness {:.17g} depth {} size {} {}\n"
                       "evaluations: {}\nbest tree{}: {}\n{}",
                       gp::to_string(reason_), pop.generation, best.id, best.fitness,
                       best.depth(s.gp.forest_depth), best.size(), experiment_->describe(best),
                       generations_->state().evaluations, best.genotype.size() > 1 ? "s" : "", trees, offsets);
}

void Generational::log_session_note() const {
    if (const std::string note = experiment_->session_note(); !note.empty()) services_.log(note);
}

std::string Generational::summary(const Stop& stop) {
    log_session_note();
    std::string text = summary_text();
    if (io::walks_a_robot(services_.settings) && !stop.interrupted) {
        try {   // the best of the final checkpoint, replayed: what its score is made of
            const auto best = report::replay(services_.run_dir.string(), "best", 1, 0.0, false);
            text += eq71_line(best.front().distance, best.front().elevation);
        } catch (const std::exception& e) {
            services_.say(std::string("note: the best's replay failed: ") + e.what());
        }
    }
    return text;
}

namespace {

const Registrar registrar{SearchKind{
    .name = "generational",
    .doc = {},   // a built-in: its name and doc are the settings' (io/search_names.cpp)
    .forms = {io::GenotypeForm::Trees},
    .keys = {},
    .budget_key = "Control.maximumIterations",
    .budget_unit = "generations",
    .claims = {},
    .claimed_by = {},
    .fallback = true,
    .load = [](const io::Settings& s, const std::string& file) -> std::unique_ptr<Checkpoint> {
        return load_population_checkpoint(s, file);
    },
    .checkpoint_schema = {},   // its io reader checks the shipped settings/cic-population.xsd
    .checkpoint_root = {},
    .best = {},
    .make = [](const Services& services, std::unique_ptr<Checkpoint> resume) -> std::unique_ptr<Search> {
        return std::make_unique<Generational>(
            services, std::unique_ptr<PopulationCheckpoint>(static_cast<PopulationCheckpoint*>(resume.release())));
    },
}};

} // namespace
} // namespace cic::search
