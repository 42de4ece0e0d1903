// What every run loop shares: stop signals, checkpoint file names, and the
// end-of-run actions of the thesis's settings (see run_support.hpp).
#include "run_support.hpp"

#include <algorithm>
#include "cic/io/experiment_types.hpp"

#include <csignal>
#include <cstdio>
#include <unistd.h>

#include <fmt/format.h>

#ifdef CIC_HAVE_MPI
#include "cic/run/mpi_pool.hpp"
#include "cic/io/settings_io.hpp"
#endif
#include "cic/report/plot.hpp"
#include "cic/core/parallel_for.hpp"
#include "cic/report/replay.hpp"
#include "cic/io/povray.hpp"
#include "cic/io/xml.hpp"
#ifdef CIC_HAVE_VIEWER
#include "cic/viz/viewer.hpp"
#endif

namespace cic::run::detail {
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

} // namespace

const std::atomic<bool>& stop_requested() { return g_interrupted; }
int stop_signal() { return g_signal.load(); }

StopSignalGuard::StopSignalGuard() {
    g_interrupted = false;
    g_signal = 0;
    previous_int_ = std::signal(SIGINT, on_stop_signal);
    previous_term_ = std::signal(SIGTERM, on_stop_signal);
}

StopSignalGuard::~StopSignalGuard() {
    std::signal(SIGINT, previous_int_);
    std::signal(SIGTERM, previous_term_);
}

RunConsole::RunConsole(const RunOptions& opt)
    : opt_(opt),
      log_(opt.run_dir / "run.log", std::ios::app),
      progress_(ProgressPrinter::for_stderr(opt.quiet ? Verbosity::Quiet
                                                      : (opt.verbose ? Verbosity::Verbose : Verbosity::Normal))) {}

void RunConsole::log(const std::string& line) { log_ << line << '\n' << std::flush; }

void RunConsole::say(const std::string& line) {
    log(line);
    progress_.message(line);
}

void RunConsole::warn(const std::string& line) {
    log(line);
    if (opt_.quiet) std::fprintf(stderr, "cic: %s\n", line.c_str());
    else progress_.message(line);
}

void RunConsole::summary(const std::string& result, RunEnd end) {
    // How the run ended (the loop's word, not the search's text), then where it
    // came from: never in population files or anything hashed.
    const std::string text = result + status_line(end) + summary_tail(started_, std::chrono::system_clock::now());
    io::xml::write_file_atomically(opt_.run_dir / "summary.txt", text);
    progress_.finish();
    log_ << text << std::flush;
    std::fputs(text.c_str(), stdout);
    std::fflush(stdout);
}

int RunConsole::interrupted() {
    const bool term = stop_signal() == SIGTERM;
    const std::string go_on =
        opt_.resume_command.empty() ? "cic resume " + opt_.run_dir.string() : opt_.resume_command;
    warn(std::string("interrupted by ") + (term ? "SIGTERM" : "SIGINT") + ": state saved to " +
         (opt_.run_dir / "population.xml").string() + "; continue with: " + go_on);
    return term ? 143 : 130;
}

int resolved_workers(const io::Settings& s) {
    return s.experiment.workers > 0 ? s.experiment.workers : hardware_threads();
}

experiments::Context make_context(const io::Settings& s, const RunOptions& opt, RunConsole& console) {
    namespace fs = std::filesystem;
    const fs::path base_dir = s.source_file.empty() ? fs::current_path() : fs::path(s.source_file).parent_path();
    const int workers = resolved_workers(s);
    experiments::Context ctx{s, base_dir, opt.run_dir / "settings.xml", opt.worker_executable, workers};
    ctx.warn = [&console](const std::string& line) { console.warn(line); };
#ifdef CIC_HAVE_MPI
    // Under mpirun with more than one rank, evaluation jobs go to ranks 1..N-1
    // (they get the settings as text: they may not see this run folder).
    if (const int ranks = mpi_world_size(); ranks > 1) {
        ctx.make_runner = [text = io::write_settings(s)] { return std::make_unique<MpiPool>(text); };
        console.say(io::evaluates_in_process(s)
                        ? fmt::format("MPI: {} ranks; symbolic regression evaluates on rank 0 with {} thread{}, the "
                                      "other ranks stay idle", ranks, workers, workers == 1 ? "" : "s")
                        : fmt::format("MPI: {} ranks, evaluation on ranks 1..{} (Experiment.workers is not used)",
                                      ranks, ranks - 1));
    }
#endif
    return ctx;
}

void write_checkpoint(const std::filesystem::path& run_dir, int generation, const std::string& text) {
    const auto checkpoint = run_dir / "populations" / population_name(generation);
    io::xml::write_file_atomically(checkpoint, text);
    point_latest_at(checkpoint, run_dir / "population.xml", text);
}

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
void finish_run(const io::Settings& s, const RunOptions& opt, RunConsole& console) {
    auto say = [&](const std::string& line) { console.say(line); };
    // Robot experiments (HyperGP, gait) have a best gait to export and show.
    const bool hypergp = io::walks_a_robot(s);
    auto attempt = [&](const char* what, auto&& action) {
        try {
            action();
        } catch (const std::exception& e) {
            say(std::string("note: ") + what + " failed: " + e.what());
        }
    };
    if (s.control.plot)
        attempt("the plot (useMatlabPlot)", [&] {
            report::plot_runs({opt.run_dir}, opt.run_dir / "fitness.svg");
            say("plot written to " + (opt.run_dir / "fitness.svg").string());
        });
    if (s.robot.generate_povray && hypergp)
        attempt("POV-Ray export (generatePovrayFiles)", [&] {
            auto items = report::replay(opt.run_dir.string(), "best", 1, 25.0, false);
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
            for (auto& item : report::replay(opt.run_dir.string(), "best", 5, 30.0, false))
                entries.push_back({{item.generation, std::to_string(item.id), item.stored_fitness},
                                   std::move(item.recording), item.centre_body});
            viz::Viewer(std::move(entries)).run();
        });
#else
        say("note: isAutonomousExperiment=0 but this cic was built without the viewer (CIC_WITH_VIEWER)");
#endif
    }
}


} // namespace cic::run::detail
