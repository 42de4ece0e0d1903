// The main job: settings -> experiment -> evolution loop, with statistics,
// checkpoints, progress and Ctrl-C handling around it.
#include "cic/app/run.hpp"

#include <csignal>
#include <unistd.h>
#include <cstdio>
#include <fstream>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#ifdef CIC_HAVE_MPI
#include "cic/app/mpi_pool.hpp"
#endif
#include "cic/app/progress.hpp"
#include "cic/core/parallel_for.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/io/stats_csv.hpp"
#include "cic/io/xml.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/experiments/experiment.hpp"
#include "cic/experiments/gait/setup.hpp"
#include "run_support.hpp"

namespace cic::app {

using detail::finish_run;
using detail::point_latest_at;
using detail::population_name;
using detail::StopSignalGuard;

PreparedRun prepare_run(io::Settings s) {
    experiments::check_inputs(s);
    PreparedRun p;
    if (!s.control.population_load_from.empty() && s.experiment.type == io::ExperimentType::Gait) {
        const std::string from = s.control.population_load_from;
        try {
            io::GaitFile loaded = io::load_gait(from);
            const gait::Setup setup = gait::Setup::from_settings(s);
            io::check_compatible(loaded, s, setup.encoding.dimension(), from);
            (void)gait::resume_search(setup, loaded, from);   // replays: a checkpoint that does not is refused now
            p.gait_resume = std::move(loaded);
        } catch (const InputError& e) {
            throw InputError("<Control> populationXmlLoadFrom: " + e.message(), e.file(), e.line());
        }
    } else if (!s.control.population_load_from.empty()) {
        const std::string from = s.control.population_load_from;   // absolute: resolved when read
        try {
            io::PopulationFile loaded = io::load_population(from);
            io::check_compatible(loaded, s, from);
            p.resume = std::move(loaded);
        } catch (const InputError& e) {
            throw InputError("<Control> populationXmlLoadFrom: " + e.message(), e.file(), e.line());
        }
    }
    p.settings = std::move(s);
    return p;
}

int run_experiment(PreparedRun prepared, const RunOptions& opt) {
    namespace fs = std::filesystem;
    if (prepared.settings.experiment.type == io::ExperimentType::Gait) return detail::run_gait(std::move(prepared), opt);
    const io::Settings& s = prepared.settings;
    const fs::path base_dir = s.source_file.empty() ? fs::current_path() : fs::path(s.source_file).parent_path();
    const int workers = s.experiment.workers > 0 ? s.experiment.workers : hardware_threads();

    std::ofstream log(opt.run_dir / "run.log", std::ios::app);
    ProgressPrinter progress = ProgressPrinter::for_stderr(
        opt.quiet ? Verbosity::Quiet : (opt.verbose ? Verbosity::Verbose : Verbosity::Normal));
    // Log lines go to run.log and, unless quiet, to the console above the progress line.
    auto say = [&](const std::string& line) {
        log << line << '\n' << std::flush;
        progress.message(line);
    };
    // Trouble (a replaced worker, a retried or failed job) reaches the console even with --quiet.
    auto warn = [&](const std::string& line) {
        log << line << '\n' << std::flush;
        if (opt.quiet) std::fprintf(stderr, "cic: %s\n", line.c_str());
        else progress.message(line);
    };

    const tree::PrimitiveSet ps(s.gp.primitives);
    experiments::Context ctx{s, base_dir, opt.run_dir / "settings.xml", opt.worker_executable, workers};
    ctx.warn = warn;
    std::string mpi_note;
#ifdef CIC_HAVE_MPI
    // Under mpirun with more than one rank, HyperGP jobs go to ranks 1..N-1 (they
    // get the settings as text: they may not see this run folder). Symbolic
    // regression has no jobs: it evaluates here with threads; the ranks idle.
    if (const int ranks = mpi_world_size(); ranks > 1) {
        ctx.make_runner = [text = io::write_settings(s)] { return std::make_unique<MpiPool>(text); };
        mpi_note = s.experiment.type == io::ExperimentType::HyperGP
            ? fmt::format("MPI: {} ranks, evaluation on ranks 1..{} (Experiment.workers is not used)", ranks, ranks - 1)
            : fmt::format("MPI: {} ranks; symbolic regression evaluates on rank 0 with {} thread{}, the other "
                          "ranks stay idle", ranks, workers, workers == 1 ? "" : "s");
    }
#endif
    auto experiment = experiments::make_experiment(ctx);

    io::PopulationFile header = io::describe(s);
    gp::EvolutionState state;
    state.seed = s.experiment.seed;
    state.rng = Rng(s.experiment.seed);
    std::optional<gp::Population> start;
    if (prepared.resume) {
        io::PopulationFile& loaded = *prepared.resume;
        const std::string& from = s.control.population_load_from;
        if (loaded.settings_digest != header.settings_digest)
            say(fmt::format("note: {} was made with other settings (digest {} vs {}); continuing with these settings",
                            from, loaded.settings_digest, header.settings_digest));
        state = loaded.state;   // the saved RNG state: a resume continues the same run
        start = std::move(loaded.population);
        say(fmt::format("resuming from {} at generation {} (seed {})", from, start->generation, state.seed));
    }

    say(fmt::format("cic {}: {} experiment, seed {}, {} worker{}, output {}", CIC_VERSION,
                    io::describe(s).experiment, state.seed, workers,
                    workers == 1 ? "" : "s", opt.run_dir.string()));
    if (!mpi_note.empty()) say(mpi_note);

    io::StatsWriter stats = opt.continue_in_place && start
        ? io::StatsWriter(opt.run_dir / "stats.csv", start->generation)
        : io::StatsWriter(opt.run_dir / "stats.csv");
    fs::create_directories(opt.run_dir / "populations");

    gp::StopConditions stop{s.control.maximum_iterations, s.control.minimum_fitness};
    gp::EvolutionHooks hooks;
    long evaluations_before = state.evaluations;
    const int first_generation = start ? start->generation + 1 : 0;
    hooks.on_generation = [&](const gp::GenerationRecord& r) {
        stats.write(r);
        log << fmt::format("gen {} best {:.17g} mean {:.17g} median {:.17g} depth {:.3f}/{} size {:.2f}/{} limit {} "
                           "illegal {} evaluations {} {:.2f}s",
                           r.generation, r.best, r.mean, r.median, r.mean_depth, r.max_depth, r.mean_size, r.max_size,
                           r.limit, r.illegal, r.evaluations, r.wall_seconds)
            << '\n' << std::flush;
        ProgressLine p;
        p.generation = r.generation;
        p.max_generations = r.max_generations;
        p.evaluations_per_second = r.generation_seconds > 0
            ? static_cast<double>(r.evaluations - evaluations_before) / r.generation_seconds : 0.0;
        evaluations_before = r.evaluations;
        p.best = r.best;
        p.mean = r.mean;
        p.limit = r.limit;
        const int done = r.generation + 1 - first_generation;
        const int left = r.max_generations - (r.generation + 1);
        p.eta_seconds = done > 0 ? r.wall_seconds / done * left : -1.0;
        progress(p);
    };
    hooks.on_checkpoint = [&](const gp::Population& pop, const gp::EvolutionState& st, bool last) {
        const int interval = std::max(1, s.experiment.checkpoint_interval);
        // After every `interval` evaluated generations (generation g is the (g+1)-th).
        if (!last && (pop.generation + 1) % interval != 0) return;
        header.population = pop;
        header.state = st;
        const std::string text = io::to_xml(header);
        const auto checkpoint = opt.run_dir / "populations" / population_name(pop.generation);
        io::xml::write_file_atomically(checkpoint, text);
        point_latest_at(checkpoint, opt.run_dir / "population.xml", text);
    };
    StopSignalGuard stop_signals;
    hooks.stop_requested = &detail::stop_requested();

    auto result = gp::evolve(s.gp, s.bloat, stop, ps, experiment->evaluator(), state, std::move(start), hooks);

    const gp::Individual& best = result.population.best();
    const std::string summary = fmt::format(
        "stopped: {} at generation {}\nbest: id {} fitness {:.17g} depth {} size {} {}\nevaluations: {}\n"
        "best tree{}: {}\n",
        gp::to_string(result.reason), result.population.generation, best.id, best.fitness, best.depth(s.gp.forest_depth), best.size(),
        experiment->describe(best), result.state.evaluations, best.genotype.size() > 1 ? "s" : "",
        [&] {
            std::string t;
            for (const auto& tr : best.genotype) t += (t.empty() ? "" : " | ") + tr.to_string();
            return t;
        }());
    io::xml::write_file_atomically(opt.run_dir / "summary.txt", summary);
    progress.finish();
    log << summary << std::flush;
    std::fputs(summary.c_str(), stdout);   // the result always reaches stdout, even with --quiet
    std::fflush(stdout);
    if (result.reason == gp::StopReason::Interrupted) {
        const bool term = detail::stop_signal() == SIGTERM;
        warn(std::string("interrupted by ") + (term ? "SIGTERM" : "SIGINT") + ": population saved to " +
             (opt.run_dir / "population.xml").string() + "; resume with Control.populationXmlLoadFrom");
        return term ? 143 : 130;
    }
    finish_run(s, opt, say);
    return 0;
}

} // namespace cic::app
