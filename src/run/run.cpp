// The main job: settings -> experiment -> evolution loop, with statistics,
// checkpoints, progress and Ctrl-C handling around it.
#include "cic/run/run.hpp"


#include <limits>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cic/run/progress.hpp"
#include "cic/core/error.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/stats_csv.hpp"
#include "cic/io/xml.hpp"
#include "cic/report/replay.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/experiment_types.hpp"
#include "cic/experiments/experiment.hpp"
#include "cic/experiments/gait/restarts.hpp"
#include "cic/experiments/gait/setup.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/experiments/map_elites_grid.hpp"
#include "run_support.hpp"

namespace cic::app {

using detail::finish_run;
using detail::make_context;
using detail::resolved_workers;
using detail::RunConsole;
using detail::StopSignalGuard;
using detail::write_checkpoint;

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

// The note on a checkpoint whose origin matched but whose search settings
// differ: its fitness values hold; the search goes on with these settings.
std::string search_note(const std::string& file_digest, const io::Settings& s, const std::string& from) {
    const std::string now = io::settings_digest(s);
    if (file_digest == now) return {};
    return fmt::format("note: {} was made with other settings (digest {}, now {}); its origin (robot, simulator, "
                       "controller) is these settings', so its fitness values hold; the budget and the search's own "
                       "settings are now these",
                       from, file_digest, now);
}

} // namespace

PreparedRun prepare_run(io::Settings s) {
    experiments::check_inputs(s);
    PreparedRun p;
    std::string file_digest;
    if (!s.control.population_load_from.empty() && s.map_elites.enabled) {
        const std::string from = s.control.population_load_from;
        try {
            io::ArchiveFile loaded = io::load_archive(from);
            p.origin_note = io::check_origin(loaded.origin, s, from);
            file_digest = loaded.settings_digest;
            const bool gait = io::family_of(s) == io::ExperimentFamily::Gait;
            std::optional<gait::Setup> setup;
            if (gait) setup = gait::Setup::from_settings(s);
            const sim::RobotSpec robot = setup ? setup->robot : hypergp::Model::from_settings(s).robot;
            io::check_compatible(loaded, s, experiments::map_elites_grid(s, robot), setup ? setup->dimension() : 0,
                                 from);
            detail::check_archive_emitter(s, loaded, from);
            p.archive_resume = std::move(loaded);
        } catch (const InputError& e) {
            throw InputError("<Control> populationXmlLoadFrom: " + e.message(), e.file(), e.line());
        }
    } else if (!s.control.population_load_from.empty() &&
               (io::family_of(s) == io::ExperimentFamily::Gait ||
                (s.neural.switches() && io::is_gait_file(s.control.population_load_from)))) {
        // A gait run's checkpoint, or one of a Switch-HybrID run's gait phase.
        const std::string from = s.control.population_load_from;
        try {
            io::GaitFile loaded = io::load_gait(from);
            p.origin_note = io::check_origin(loaded.origin, s, from);
            file_digest = loaded.settings_digest;
            const gait::Setup setup = gait::Setup::from_settings(s);
            io::check_compatible(loaded, s, setup.dimension(), from);
            (void)gait::resume_search(setup, gait::restart_rule_of(s), loaded, from);   // replays: a checkpoint that does not is refused now
            p.gait_resume = std::move(loaded);
        } catch (const InputError& e) {
            throw InputError("<Control> populationXmlLoadFrom: " + e.message(), e.file(), e.line());
        }
    } else if (!s.control.population_load_from.empty()) {
        const std::string from = s.control.population_load_from;   // absolute: resolved when read
        try {
            io::PopulationFile loaded = io::load_population(from);
            p.origin_note = io::check_origin(loaded.origin, s, from);
            file_digest = loaded.settings_digest;
            io::check_compatible(loaded, s, from);
            check_direct_offsets(loaded, s, from);
            p.resume = std::move(loaded);
        } catch (const InputError& e) {
            throw InputError("<Control> populationXmlLoadFrom: " + e.message(), e.file(), e.line());
        }
    }
    if (!s.control.population_load_from.empty())
        p.search_note = search_note(file_digest, s, s.control.population_load_from);
    p.settings = std::move(s);
    return p;
}

namespace {

// Where the loop starts: a fresh state from the seed, or the loaded population
// with its saved state (a resume continues the same run).
struct Start {
    gp::EvolutionState state;
    std::optional<gp::Population> population;
};

Start start_of(PreparedRun& prepared, RunConsole& console) {
    const io::Settings& s = prepared.settings;
    Start out;
    out.state.seed = s.experiment.seed;
    out.state.rng = Rng(s.experiment.seed);
    if (!prepared.resume) return out;
    io::PopulationFile& loaded = *prepared.resume;
    const std::string& from = s.control.population_load_from;
    out.state = loaded.state;
    out.population = std::move(loaded.population);
    console.say(fmt::format("resuming from {} at generation {} (seed {})", from, out.population->generation,
                            out.state.seed));
    return out;
}

// What the run does after each generation: stats.csv, run.log, the progress
// line, and every Experiment.checkpointInterval generations a population file.
class GenerationObserver {
public:
    GenerationObserver(const io::Settings& s, const RunOptions& opt, RunConsole& console, io::PopulationFile header,
                       const Start& start)
        : s_(s), opt_(opt), console_(console), header_(std::move(header)),
          stats_(opt.continue_in_place && start.population
                     ? io::StatsWriter(opt.run_dir / "stats.csv", start.population->generation)
                     : io::StatsWriter(opt.run_dir / "stats.csv")),
          evaluations_before_(start.state.evaluations),
          first_generation_(start.population ? start.population->generation + 1 : 0) {
        std::filesystem::create_directories(opt.run_dir / "populations");
    }

    gp::EvolutionHooks hooks() {
        gp::EvolutionHooks h;
        h.on_generation = [this](const gp::GenerationRecord& r) { on_generation(r); };
        h.on_checkpoint = [this](const gp::Population& p, const gp::EvolutionState& st, bool last) {
            on_checkpoint(p, st, last);
        };
        h.stop_requested = &detail::stop_requested();
        return h;
    }

private:
    void on_generation(const gp::GenerationRecord& r) {
        stats_.write(r);
        console_.log(fmt::format("gen {} best {:.17g} mean {:.17g} median {:.17g} depth {:.3f}/{} size {:.2f}/{} limit "
                                 "{} illegal {} evaluations {} {:.2f}s",
                                 r.generation, r.best, r.mean, r.median, r.mean_depth, r.max_depth, r.mean_size,
                                 r.max_size, r.limit, r.illegal, r.evaluations, r.wall_seconds));
        ProgressLine p;
        p.generation = r.generation;
        p.max_generations = progress_generations > 0 ? progress_generations : r.max_generations;
        p.evaluations_per_second = r.generation_seconds > 0
            ? static_cast<double>(r.evaluations - evaluations_before_) / r.generation_seconds : 0.0;
        evaluations_before_ = r.evaluations;
        p.best = r.best;
        p.mean = r.mean;
        p.limit = r.limit;
        const int done = r.generation + 1 - first_generation_;
        const int left = p.max_generations - (r.generation + 1);
        p.eta_seconds = done > 0 ? r.wall_seconds / done * left : -1.0;
        console_.progress(p);
    }

public:
    // Adds a phase's own state to each checkpoint (Switch-HybrID's clock).
    std::function<void(io::PopulationFile&)> annotate;
    // The generations the progress line counts to, when not maximumIterations (0).
    int progress_generations = 0;

private:
    void on_checkpoint(const gp::Population& pop, const gp::EvolutionState& st, bool last) {
        const int interval = std::max(1, s_.experiment.checkpoint_interval);
        // After every `interval` evaluated generations (generation g is the (g+1)-th).
        if (!last && (pop.generation + 1) % interval != 0) return;
        header_.population = pop;
        header_.state = st;
        if (annotate) annotate(header_);
        write_checkpoint(opt_.run_dir, pop.generation, io::to_xml(header_));
    }

    const io::Settings& s_;
    const RunOptions& opt_;
    RunConsole& console_;
    io::PopulationFile header_;
    io::StatsWriter stats_;
    long evaluations_before_;
    int first_generation_;
};

} // namespace

namespace detail {

std::string summary_of(const gp::EvolutionResult& result, const experiments::Experiment& experiment,
                       const io::Settings& s) {
    const gp::Individual& best = result.population.best();
    std::string trees;
    for (const auto& t : best.genotype) trees += (trees.empty() ? "" : " | ") + t.to_string();
    std::string offsets;
    if (!best.direct.empty()) offsets = fmt::format("best direct offsets (x pi/2 rad): {:.4f}\n", fmt::join(best.direct, " "));
    return fmt::format("stopped: {} at generation {}\nbest: id {} fitness {:.17g} depth {} size {} {}\n"
                       "evaluations: {}\nbest tree{}: {}\n{}",
                       gp::to_string(result.reason), result.population.generation, best.id, best.fitness,
                       best.depth(s.gp.forest_depth), best.size(), experiment.describe(best),
                       result.state.evaluations, best.genotype.size() > 1 ? "s" : "", trees, offsets);
}

GpPhaseResult run_gp_phase(PreparedRun& prepared, const RunOptions& opt, RunConsole& console, const GpPhase& phase) {
    const io::Settings& s = prepared.settings;
    io::PopulationFile header = io::describe(s);
    detail::say_checkpoint_notes(prepared, console);
    Start start = start_of(prepared, console);
    const int workers = resolved_workers(s);
    console.say(fmt::format("cic {}: {} experiment, seed {}, {} worker{}, output {}", CIC_VERSION, header.experiment,
                            start.state.seed, workers, workers == 1 ? "" : "s", opt.run_dir.string()));
    const experiments::Context ctx = make_context(s, opt, console);
    GpPhaseResult out;
    out.experiment = experiments::make_experiment(ctx);
    auto& experiment = out.experiment;
    gp::GpConfig gp = s.gp;
    gp.direct = experiment->direct_genes();   // Offset-HybrID's offsets, else none
    header.offsets = gp.direct.count;
    header.offset_limit = gp.direct.count > 0 ? gp.direct.limit : 0.0;
    // What the evaluations column counts, where it is first seen.
    console.log(fmt::format("evaluations count every individual evaluated: a generation evaluates its new individuals "
                            "only (elites and reproduced copies keep their fitness){}",
                            s.bloat.enabled ? ", and under Dynamic Limits also each child bred past the depth limit, "
                                              "which is then replaced by its parent unless it beats the best: so a "
                                              "generation may evaluate fewer or more than its population"
                                            : ""));

    GenerationObserver observer(s, opt, console, header, start);
    observer.annotate = phase.annotate;
    observer.progress_generations = phase.progress_generations;
    gp::EvolutionHooks hooks = observer.hooks();
    if (phase.on_generation)
        hooks.on_generation = [observer_hook = hooks.on_generation, &phase](const gp::GenerationRecord& r) {
            phase.on_generation(r);   // first: the checkpoint's annotation reads what it noted
            observer_hook(r);
        };
    hooks.hand_over = phase.hand_over;
    const tree::PrimitiveSet ps(s.gp.primitives);
    gp::StopConditions stop{s.control.maximum_iterations, s.control.minimum_fitness};
    if (phase.hand_over) stop.maximum_iterations = std::numeric_limits<int>::max();   // the phase ends by hand_over
    out.result = gp::evolve(gp, s.bloat, stop, ps, experiment->evaluator(), start.state, std::move(start.population),
                            hooks);
    if (const std::string note = experiment->session_note(); !note.empty()) console.log(note);
    return out;
}

} // namespace detail

int run_experiment(PreparedRun prepared, const RunOptions& opt) {
    // The loop is the family's: the gait family's own, else the GP loop with the type's evaluator.
    if (prepared.settings.map_elites.enabled) return detail::run_map_elites(std::move(prepared), opt);
    if (io::family_of(prepared.settings) == io::ExperimentFamily::Gait) return detail::run_gait(std::move(prepared), opt);
    if (prepared.settings.neural.switches()) return detail::run_switch(std::move(prepared), opt);
    const io::Settings& s = prepared.settings;
    RunConsole console(opt);
    StopSignalGuard stop_signals;
    const detail::GpPhaseResult phase = detail::run_gp_phase(prepared, opt, console, {});
    const gp::EvolutionResult& result = phase.result;
    std::string summary = detail::summary_of(result, *phase.experiment, s);
    if (io::family_of(s) == io::ExperimentFamily::HyperGP && result.reason != gp::StopReason::Interrupted) {
        try {   // the best of the final checkpoint, replayed: what its score is made of
            const auto best = replay(opt.run_dir.string(), "best", 1, 0.0, false);
            summary += detail::eq71_line(best.front().distance, best.front().elevation);
        } catch (const std::exception& e) {
            console.say(std::string("note: the best's replay failed: ") + e.what());
        }
    }
    console.summary(summary);
    if (result.reason == gp::StopReason::Interrupted) return console.interrupted();
    finish_run(s, opt, console);
    return 0;
}

} // namespace cic::app
