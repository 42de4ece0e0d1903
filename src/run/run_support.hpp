#pragma once
// Private to src/run: what the run loop (run.cpp) uses around a search.
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
#include "cic/run/run_status.hpp"
#include "cic/experiments/experiment.hpp"
#include "cic/gp/evolution.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings.hpp"

namespace cic::run::detail {

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
    // summary.txt (atomically), run.log, and stdout even with --quiet: the
    // search's TEXT, how the run ended (run_status.hpp) and where it came from.
    void summary(const std::string& text, RunEnd end);
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

} // namespace cic::run::detail
