// The evolution strategies on an open-loop gait (experiments/gait/): pagmo2's
// CMA-ES, xNES or SaDE, or cic's separable CMA-ES (Gait.optimizer), with IPOP
// restarts (Gait.restarts), one generation per step, within the budget
// Gait.evaluations. Its checkpoint is the gait file (io/gait_xml.hpp): the
// seed and every fitness returned, from which the search replays exactly.
#include "evolution_strategy.hpp"

#include <fstream>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/report/replay.hpp"
#include "cic/sim/evaluate.hpp"
#include "cic/search/support.hpp"

namespace cic::search {
namespace {

// After kStatsColumns: the best fitness of the run so far (`best` is each generation's).
constexpr const char* kGaitStatsColumns = "best_so_far";

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

} // namespace

void GaitCheckpoint::check_goes_on(const io::Settings& s) const {
    refuse_if_reached(gait.champion.fitness, s, file);
    // A Switch-HybrID gait phase counts on from its HyperGP phase's evaluations.
    const long spent = gait.evaluations + (gait.handover ? gait.handover->evaluations : 0);
    const long batch = search->next_batch_size();
    if (spent + batch > s.gait.evaluations)
        throw InputError(fmt::format("the run has spent {} evaluations; a budget of {} adds no generation of {} (ask "
                                     "for --set Gait.evaluations={} or more)",
                                     spent, s.gait.evaluations, batch, spent + batch),
                         file);
}

std::unique_ptr<GaitCheckpoint> load_gait_checkpoint(const io::Settings& s, const std::string& file) {
    auto c = std::make_unique<GaitCheckpoint>();
    c->file = file;
    c->gait = io::load_gait(file);
    c->origin_note = io::check_origin(c->gait.origin, s, file);
    c->settings_digest = c->gait.settings_digest;
    c->generations = c->gait.generation + 1;
    // A Switch-HybrID gait phase numbers on from its HyperGP phase (EvolutionStrategy::checkpoint).
    c->number = (c->gait.handover ? c->gait.handover->generation + 1 : 0) + c->gait.generation;
    c->evaluations = c->gait.evaluations + (c->gait.handover ? c->gait.handover->evaluations : 0);
    const gait::Setup setup = gait::Setup::from_settings(s);
    io::check_compatible(c->gait, s, setup.dimension(), file);
    // Replays: a checkpoint that does not is refused now.
    c->search.emplace(gait::resume_search(setup, gait::restart_rule_of(s), c->gait, file));
    return c;
}

EvolutionStrategy::EvolutionStrategy(const Services& services, std::unique_ptr<GaitCheckpoint> resume,
                                     std::optional<io::GaitHandover> handover, std::string summary_head)
    : services_(services), resume_(std::move(resume)), handover_(std::move(handover)),
      summary_head_(std::move(summary_head)), setup_(gait::Setup::from_settings(services.settings)),
      rule_(gait::restart_rule_of(services.settings)), origin_(io::origin_of(services.settings, setup_.robot)) {
    if (handover_) {
        at_generation_ = handover_->generation + 1;
        at_evaluations_ = handover_->evaluations;
    }
    // A run resumed in place from a file written before the column keeps its header;
    // a Switch-HybrID run's stats.csv has its HyperGP phase's columns.
    with_best_so_far_ = !handover_;
    if (with_best_so_far_ && resume_ && services_.continue_in_place) {
        std::ifstream in(services_.run_dir / "stats.csv");
        std::string header;
        std::getline(in, header);
        with_best_so_far_ = header.empty() || header.find(",best_so_far") != std::string::npos;
    }
}

StatsLayout EvolutionStrategy::stats_layout() const {
    StatsLayout l;
    l.extra_columns = with_best_so_far_ ? kGaitStatsColumns : "";
    if (resume_ && services_.continue_in_place) l.continue_after = at_generation_ + resume_->gait.generation;
    // Switch-HybrID's gait phase goes on from the HyperGP phase's rows (the same writer).
    return l;
}

std::optional<Row> EvolutionStrategy::start() {
    const io::Settings& s = services_.settings;
    const bool ipop = rule_.mode == gait::Restarts::Ipop;
    if (resume_) {
        search_ = std::move(resume_->search);
    } else {
        search_.emplace(gait::make_search(setup_, rule_, s.experiment.seed));
        if (handover_) search_->set_start(handover_->x);   // Switch-HybrID: from HyperGP's best
    }
    restarts_said_ = search_->restarts();
    const int workers = services_.context.workers;
    services_.say(fmt::format("cic {}: gait experiment ({} over {} parameters, {} candidates per generation, budget "
                              "{} evaluations), seed {}, {} worker{}, output {}",
                              CIC_VERSION, gait::to_string(setup_.optimizer), setup_.dimension(), setup_.population,
                              s.gait.evaluations, s.experiment.seed, workers, workers == 1 ? "" : "s",
                              services_.run_dir.string()));
    if (!ipop && s.gait.evaluations % setup_.population != 0)   // whole generations only: said, not done silently
        services_.say(fmt::format("note: Gait.evaluations {} is not a whole number of generations of {} candidates; "
                                  "the run stops after {} generations, at {} evaluations",
                                  s.gait.evaluations, setup_.population, s.gait.evaluations / setup_.population,
                                  s.gait.evaluations / setup_.population * setup_.population));
    if (ipop)
        services_.say(fmt::format(
            "ipop restarts: a start stagnates when its best rises by <= {:g} over {} generations{}; each restart "
            "doubles the population",
            rule_.tolerance, rule_.patience > 0 ? std::to_string(rule_.patience) : "10 + ceil(30 n / lambda)",
            rule_.tol_x > 0 ? fmt::format(", or collapses below a spread of {:g}", rule_.tol_x) : ""));
    evaluator_ = std::make_unique<gait::Evaluator>(services_.context, setup_);
    batch_ = [this](const std::vector<std::vector<double>>& xs) { return (*evaluator_)(xs); };
    if (resume_) {
        say_checkpoint_notes(*resume_, services_);
        services_.say(fmt::format("resuming from {} at generation {} ({} evaluations)", resume_->file,
                                  resume_->gait.generation, resume_->gait.evaluations));
        first_generation_ = search_->generation();
        return std::nullopt;
    }
    const auto t0 = std::chrono::steady_clock::now();
    search_->initialise(batch_);
    first_generation_ = search_->generation();
    return after_generation(seconds_since(t0));
}

Row EvolutionStrategy::after_generation(double generation_seconds) {
    const io::Settings& s = services_.settings;
    gait::Search& search = *search_;
    if (search.restarts() > restarts_said_) {
        restarts_said_ = search.restarts();
        services_.say(fmt::format("restart {}: population {} from generation {}, after {} generations without "
                                  "improvement of more than {:g}{}",
                                  search.restarts(), search.population_size(), at_generation_ + search.generation(),
                                  last_stalled_, rule_.tolerance,
                                  last_collapsed_ ? " (the candidates had collapsed)" : ""));
    }
    Row row;
    gp::GenerationRecord& r = row.record;
    r.generation = at_generation_ + search.generation();
    std::vector<double> f;
    for (const auto& c : search.population()) f.push_back(c.fitness);
    fill_fitness_stats(r, std::move(f));
    r.evaluations = at_evaluations_ + search.evaluations();
    r.failed = static_cast<int>(evaluator_->failed() - failed_before_);
    r.wall_seconds = seconds_since(started_);
    r.generation_seconds = generation_seconds;
    failed_before_ = evaluator_->failed();
    // `best` is this generation's; best_so_far the run's (the console's and the replay's).
    if (with_best_so_far_) row.extra = fmt::format("{:.17g}", search.champion().fitness);
    row.log = fmt::format("gen {} best {:.17g} mean {:.17g} median {:.17g} champion {:.17g} evaluations {} {:.2f}s",
                          r.generation, r.best, r.mean, r.median, search.champion().fitness, r.evaluations,
                          r.wall_seconds);
    // The generations the budget allows at the next batch's size (without restarts: floor(budget / lambda)).
    const int max_generations =
        r.generation + 1 + static_cast<int>(std::max(0L, s.gait.evaluations - r.evaluations) / search.next_batch_size());
    ProgressLine& p = row.progress;
    p.generation = r.generation;
    p.max_generations = max_generations;
    p.evaluations_per_second = generation_seconds > 0 ? search.population_size() / generation_seconds : 0.0;
    p.best = search.champion().fitness;
    p.mean = r.mean;
    p.eta_seconds = generation_seconds * std::max(0, max_generations - (r.generation + 1));
    stepped_ = true;
    return row;
}

Stop EvolutionStrategy::stop(bool signal) {
    const io::Settings& s = services_.settings;
    if (search_->champion().fitness >= s.control.minimum_fitness) return {"minimum fitness reached", false};
    if (signal) return {"interrupted", true};
    if (at_evaluations_ + search_->evaluations() + search_->next_batch_size() > s.gait.evaluations)
        return {"evaluation budget", false};
    return {};
}

bool EvolutionStrategy::checkpoint_due(const Stop& stop) {
    const io::Settings& s = services_.settings;
    const bool stepped = std::exchange(stepped_, false);
    const int generation = at_generation_ + search_->generation();
    const long evaluations = at_evaluations_ + search_->evaluations();
    const int interval = std::max(1, s.experiment.checkpoint_interval);
    if (stepped && ((generation + 1) % interval == 0 || s.gait.evaluations - evaluations < search_->next_batch_size()))
        return true;
    // The checkpoint of the last finished generation, unless the interval skipped it.
    if (stop.interrupted) return true;
    // A resume from a run's last checkpoint ends at once: the run's final state
    // goes into this folder too (as the GP loop saves a resumed last generation again).
    return stop.done() && resume_ && search_->generation() == first_generation_;
}

CheckpointText EvolutionStrategy::checkpoint() const {
    const io::Settings& s = services_.settings;
    const gait::Search& search = *search_;
    io::GaitFile g;
    g.origin = origin_;
    g.settings_digest = io::settings_digest(s);
    g.optimizer = gait::to_string(search.optimizer());
    g.seed = search.seed();
    g.generation = search.generation();
    g.evaluations = search.evaluations();
    g.dimension = search.dimension();
    for (const auto& c : search.population()) g.population.push_back({c.x, c.fitness});
    g.champion = {search.champion().x, search.champion().fitness};
    g.history = search.history();
    if (search.restart_rule().mode != gait::Restarts::None) g.restarts = gait::restart_record_of(search);
    g.handover = handover_;
    return {at_generation_ + search.generation(), io::to_xml(g)};
}

Row EvolutionStrategy::step() {
    const auto t0 = std::chrono::steady_clock::now();
    last_stalled_ = search_->stalled_generations();
    last_collapsed_ = search_->collapsed();
    search_->step(batch_);
    return after_generation(seconds_since(t0));
}

std::string EvolutionStrategy::summary(const Stop& stop) {
    const gait::Search& search = *search_;
    const gait::Candidate& best = search.champion();
    std::string text =
        summary_head_ +
        fmt::format("stopped: {} at generation {}\nbest: fitness {:.17g} ({}; robot {})\nevaluations: {}\nbest gait: {}\n",
                    stop.reason, at_generation_ + search.generation(), best.fitness,
                    gait::to_string(setup_.optimizer), setup_.robot.name, at_evaluations_ + search.evaluations(),
                    setup_.describe(best.x));
    if (rule_.mode == gait::Restarts::Ipop)
        text += fmt::format("restarts: {} (population {})\n", search.restarts(), search.population_size());
    if (!stop.interrupted) {   // the champion again: what its score is made of
        const auto controller = setup_.controller(best.x);
        const sim::EvalResult r = sim::evaluate(setup_.robot, *controller, setup_.sim);
        const auto [distance, elevation] = report::eq71_terms(setup_.robot, r);
        text += eq71_line(distance, elevation);
    }
    return text;
}

namespace {

const Registrar registrar{SearchKind{
    .name = "evolution-strategy",
    .doc = {},   // a built-in: its name and doc are the settings' (io/search_names.cpp)
    .forms = {io::GenotypeForm::Vector},
    .keys = {},
    .budget_key = "Gait.evaluations",
    .budget_unit = "evaluations",
    .claims = {},
    .claimed_by = {},
    .fallback = true,
    .load = [](const io::Settings& s, const std::string& file) -> std::unique_ptr<Checkpoint> {
        return load_gait_checkpoint(s, file);
    },
    .checkpoint_schema = {},   // its io reader checks the shipped settings/cic-gait.xsd
    .checkpoint_root = {},
    .best = {},
    .make = [](const Services& services, std::unique_ptr<Checkpoint> resume) -> std::unique_ptr<Search> {
        return std::make_unique<EvolutionStrategy>(
            services, std::unique_ptr<GaitCheckpoint>(static_cast<GaitCheckpoint*>(resume.release())));
    },
}};

} // namespace
} // namespace cic::search
