#pragma once
// Private to src/run: what the run loops (run.cpp for GP experiments,
// run_gait.cpp for the gait baseline) share.
#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <chrono>

#include "cic/run/progress.hpp"
#include "cic/run/provenance.hpp"
#include "cic/run/run.hpp"
#include "cic/experiments/experiment.hpp"
#include "cic/gp/evolution.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings.hpp"

namespace cic::app::detail {

// Ctrl-C or a batch scheduler's SIGTERM: the loop finishes the generation under
// way, writes its checkpoint and leaves; a second signal ends the process at
// once. The guard installs the handlers for a run and restores the old ones.
class StopSignalGuard {
public:
    StopSignalGuard();
    ~StopSignalGuard();
    StopSignalGuard(const StopSignalGuard&) = delete;
    StopSignalGuard& operator=(const StopSignalGuard&) = delete;

private:
    using Handler = void (*)(int);
    Handler previous_int_, previous_term_;
};
const std::atomic<bool>& stop_requested();
int stop_signal();   // SIGINT or SIGTERM, whichever came first; 0 = none

// A run's voice: run.log, the console's progress line and stdout's summary.
class RunConsole {
public:
    explicit RunConsole(const RunOptions& opt);
    // run.log and, unless --quiet, the console above the progress line.
    void say(const std::string& line);
    // Trouble that does not stop the run (a replaced worker, a failed job):
    // run.log and the console, even with --quiet.
    void warn(const std::string& line);
    // run.log only.
    void log(const std::string& line);
    void progress(const ProgressLine& line) { progress_(line); }
    // summary.txt (atomically), run.log, and stdout even with --quiet.
    void summary(const std::string& text);
    // After a stop signal: says where the state was saved; returns the exit
    // code (130 for SIGINT, 143 for SIGTERM).
    int interrupted();

private:
    const RunOptions& opt_;
    std::chrono::system_clock::time_point started_ = std::chrono::system_clock::now();
    std::ofstream log_;
    ProgressPrinter progress_;
};

// Experiment.workers, or with 0 the machine's hardware threads.
int resolved_workers(const io::Settings& s);

// The evaluation context of a run: settings, folders, resolved worker count,
// warnings to `console`, and under mpirun with several ranks the MPI runner
// (said on the console). Symbolic regression evaluates in-process with
// threads, so under MPI its extra ranks idle.
experiments::Context make_context(const io::Settings& s, const RunOptions& opt, RunConsole& console);

// populations/gen-NNNN.xml
std::string population_name(int generation);

// population.xml becomes a second name of the checkpoint just written.
void point_latest_at(const std::filesystem::path& checkpoint, const std::filesystem::path& latest,
                     const std::string& text);

// Writes populations/gen-NNNN.xml atomically and points population.xml at it.
void write_checkpoint(const std::filesystem::path& run_dir, int generation, const std::string& text);

// The end-of-run actions of the settings: plot (useMatlabPlot), POV-Ray scenes
// (generatePovrayFiles) and showing the best (isAutonomousExperiment = 0).
void finish_run(const io::Settings& s, const RunOptions& opt, RunConsole& console);

// best, mean and median of a generation's (or an archive's) fitness values;
// leaves them 0 when there is none.
void fill_fitness_stats(gp::GenerationRecord& r, std::vector<double> fitness);

// The summary line that splits the best's score into eq. 7.1's terms.
std::string eq71_line(double distance, double elevation);

// The GP loop of run_experiment (run.cpp) as one phase of a run: the
// experiment's evaluator, stats.csv rows, run.log lines, progress and
// checkpoints. Without hooks it is the whole GP run. A caller holds the
// StopSignalGuard (one for all of a run's phases).
struct GpPhase {
    // Called with each generation's record before stats.csv and the checkpoint see it.
    std::function<void(const gp::GenerationRecord&)> on_generation;
    // Adds the phase's own state to each checkpoint.
    std::function<void(io::PopulationFile&)> annotate;
    // Ends the phase after a generation (gp::EvolutionHooks::hand_over);
    // with it Control.maximumIterations does not apply.
    std::function<bool(const gp::GenerationRecord&)> hand_over;
    // What the progress line counts to instead of maximumIterations; 0 = that.
    int progress_generations = 0;
};
struct GpPhaseResult {
    gp::EvolutionResult result;
    std::unique_ptr<experiments::Experiment> experiment;
};
GpPhaseResult run_gp_phase(PreparedRun& prepared, const RunOptions& opt, RunConsole& console, const GpPhase& phase);
// "stopped: ... best: ... best trees: ..." of summary.txt.
std::string summary_of(const gp::EvolutionResult& result, const experiments::Experiment& experiment,
                       const io::Settings& s);
// The prepared run's notes on its checkpoint (origin_note, search_note), if any.
void say_checkpoint_notes(const PreparedRun& prepared, RunConsole& console);

// The gait experiment's loop (run_gait.cpp); run_experiment hands over to it.
int run_gait(PreparedRun prepared, const RunOptions& opt);
// The gait loop as a later phase of a run (Switch-HybrID): `handover` says
// where the HyperGP phase ended and where the search starts (its generations
// and evaluations continue the run's); prepared.gait_resume, when set, is this
// phase's own checkpoint. `summary_head` opens summary.txt. A caller holds the
// StopSignalGuard.
int run_gait_phase(PreparedRun& prepared, const RunOptions& opt, RunConsole& console,
                   const std::optional<io::GaitHandover>& handover, const std::string& summary_head);
// Switch-HybrID (run_switch.cpp): the GP phase, then the gait phase.
int run_switch(PreparedRun prepared, const RunOptions& opt);
// The MAP-Elites loop of either robot family (run_map_elites.cpp).
int run_map_elites(PreparedRun prepared, const RunOptions& opt);
// Throws cic::InputError naming `file` when the archive's emitter state is one
// the settings' emitter cannot take back (before a resume writes anything).
void check_archive_emitter(const io::Settings& s, const io::ArchiveFile& a, const std::string& file);

} // namespace cic::app::detail
