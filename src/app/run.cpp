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
#include "cic/app/plot.hpp"
#include "cic/app/progress.hpp"
#include "cic/app/replay.hpp"
#include "cic/io/povray.hpp"
#ifdef CIC_HAVE_VIEWER
#include "cic/viz/viewer.hpp"
#endif
#include "cic/core/process_pool.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/io/stats_csv.hpp"
#include "cic/io/xml.hpp"
#include "experiments/experiment.hpp"

namespace cic::app {
namespace {

std::atomic<bool> g_interrupted{false};
std::atomic<int> g_signal{0};   // SIGINT or SIGTERM, whichever came first

// Ctrl-C or a batch scheduler's SIGTERM (Slurm sends it before a kill): finish the
// generation under way, write the checkpoint and leave. A second signal of either
// kind ends the process at once (the handlers are reset to the default).
extern "C" void on_stop_signal(int sig) {
    int none = 0;
    g_signal.compare_exchange_strong(none, sig);
    g_interrupted.store(true);
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
}

// Restores the previous handlers when the run ends.
struct StopSignalGuard {
    using Handler = void (*)(int);
    Handler previous_int, previous_term;
    StopSignalGuard() {
        g_interrupted = false;
        g_signal = 0;
        previous_int = std::signal(SIGINT, on_stop_signal);
        previous_term = std::signal(SIGTERM, on_stop_signal);
    }
    ~StopSignalGuard() {
        std::signal(SIGINT, previous_int);
        std::signal(SIGTERM, previous_term);
    }
};

std::string population_name(int generation) { return fmt::format("gen-{:04d}.xml", generation); }

// population.xml becomes a second name of the checkpoint just written (a hard
// link renamed into place: atomic, and no second copy to write and fsync). Where
// links are not supported, it is written as a copy.
void point_latest_at(const std::filesystem::path& checkpoint, const std::filesystem::path& latest,
                     const std::string& text) {
    const auto tmp = latest.string() + ".link-" + std::to_string(::getpid());
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    std::filesystem::create_hard_link(checkpoint, tmp, ec);
    if (!ec) std::filesystem::rename(tmp, latest, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        io::xml::write_file_atomically(latest, text);
    }
}

// What the thesis did when a run ended (Appendix B): plots (useMatlabPlot, now
// gnuplot), POV-Ray scenes of the best (generatePovrayFiles) and showing the best
// (isAutonomousExperiment = 0). A failure here is reported, never loses the run.
template <class Say>
void finish_run(const io::Settings& s, const RunOptions& opt, Say& say) {
    const bool hypergp = s.experiment.type == io::ExperimentType::HyperGP;
    auto attempt = [&](const char* what, auto&& action) {
        try {
            action();
        } catch (const std::exception& e) {
            say(std::string("note: ") + what + " failed: " + e.what());
        }
    };
    if (s.control.plot)
        attempt("the plot (useMatlabPlot)", [&] {
            plot_runs({opt.run_dir}, opt.run_dir / "fitness.svg");
            say("plot written to " + (opt.run_dir / "fitness.svg").string());
        });
    if (s.robot.generate_povray && hypergp)
        attempt("POV-Ray export (generatePovrayFiles)", [&] {
            auto items = replay(opt.run_dir.string(), "best", 1, 25.0, false);
            io::PovrayOptions po;
            po.centre_body = items.front().centre_body;
            po.title = items.front().label;
            const int n = io::write_povray(items.front().recording, opt.run_dir / "povray", 25.0, po);
            say(fmt::format("{} POV-Ray scenes of the best written to {}; render them with scripts/render-video.sh {}",
                            n, (opt.run_dir / "povray").string(), (opt.run_dir / "povray").string()));
        });
    if (!s.control.autonomous && hypergp) {
#ifdef CIC_HAVE_VIEWER
        attempt("showing the best (isAutonomousExperiment=0)", [&] {
            std::vector<viz::ViewEntry> entries;
            for (auto& item : replay(opt.run_dir.string(), "best", 5, 30.0, false))
                entries.push_back({{item.generation, std::to_string(item.id), item.stored_fitness},
                                   std::move(item.recording), item.centre_body});
            viz::Viewer(std::move(entries)).run();
        });
#else
        say("note: isAutonomousExperiment=0 but this cic was built without the viewer (CIC_WITH_VIEWER)");
#endif
    }
}

} // namespace

PreparedRun prepare_run(io::Settings s) {
    experiments::check_inputs(s);
    PreparedRun p;
    if (!s.control.population_load_from.empty()) {
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
        say(fmt::format("resuming from {} at generation {} (seed {})", from, start->iteration, state.seed));
    }

    say(fmt::format("cic {}: {} experiment, seed {}, {} worker{}, output {}", CIC_VERSION,
                    s.experiment.type == io::ExperimentType::HyperGP ? "hypergp" : "symreg", state.seed, workers,
                    workers == 1 ? "" : "s", opt.run_dir.string()));
    if (!mpi_note.empty()) say(mpi_note);

    io::StatsWriter stats = opt.continue_in_place && start
        ? io::StatsWriter(opt.run_dir / "stats.csv", start->iteration)
        : io::StatsWriter(opt.run_dir / "stats.csv");
    fs::create_directories(opt.run_dir / "populations");

    gp::StopConditions stop{s.control.maximum_iterations, s.control.minimum_fitness};
    gp::EvolutionHooks hooks;
    long evaluations_before = state.evaluations;
    const int first_generation = start ? start->iteration + 1 : 0;
    hooks.on_generation = [&](const gp::GenerationRecord& r) {
        stats.write(r);
        log << fmt::format("gen {} best {:.17g} mean {:.17g} median {:.17g} depth {:.3f}/{} size {:.2f}/{} limit {} "
                           "illegal {} evaluations {} {:.2f}s",
                           r.generation, r.best, r.mean, r.median, r.mean_depth, r.max_depth, r.mean_size, r.max_size,
                           r.limit, r.illegal, r.evaluations, r.wall_seconds)
            << '\n' << std::flush;
        GenerationRecord p;
        p.generation = r.generation + 1;
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
        if (!last && (pop.iteration + 1) % interval != 0) return;
        header.population = pop;
        header.state = st;
        const std::string text = io::to_xml(header);
        const auto checkpoint = opt.run_dir / "populations" / population_name(pop.iteration);
        io::xml::write_file_atomically(checkpoint, text);
        point_latest_at(checkpoint, opt.run_dir / "population.xml", text);
    };
    StopSignalGuard stop_signals;
    hooks.stop_requested = &g_interrupted;

    auto result = gp::evolve(s.gp, s.bloat, stop, ps, experiment->evaluator(), state, std::move(start), hooks);

    const gp::Individual& best = result.population.best();
    const std::string summary = fmt::format(
        "stopped: {} at generation {}\nbest: id {} fitness {:.17g} depth {} size {} {}\nevaluations: {}\n"
        "best tree{}: {}\n",
        gp::to_string(result.reason), result.population.iteration, best.id, best.fitness, best.depth(s.gp.forest_depth), best.size(),
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
        const bool term = g_signal.load() == SIGTERM;
        warn(std::string("interrupted by ") + (term ? "SIGTERM" : "SIGINT") + ": population saved to " +
             (opt.run_dir / "population.xml").string() + "; resume with Control.populationXmlLoadFrom");
        return term ? 143 : 130;
    }
    finish_run(s, opt, say);
    return 0;
}

} // namespace cic::app
