#pragma once
// Private to src/app: what the run loops (run.cpp for GP experiments,
// run_gait.cpp for the gait baseline) share.
#include <atomic>
#include <filesystem>
#include <functional>
#include <string>

#include "cic/app/run.hpp"
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

// populations/gen-NNNN.xml
std::string population_name(int generation);

// population.xml becomes a second name of the checkpoint just written.
void point_latest_at(const std::filesystem::path& checkpoint, const std::filesystem::path& latest,
                     const std::string& text);

// The end-of-run actions of the settings: plot (useMatlabPlot), POV-Ray scenes
// (generatePovrayFiles) and showing the best (isAutonomousExperiment = 0).
void finish_run(const io::Settings& s, const RunOptions& opt, const std::function<void(const std::string&)>& say);

// The gait experiment's loop (run_gait.cpp); run_experiment hands over to it.
int run_gait(PreparedRun prepared, const RunOptions& opt);

} // namespace cic::app::detail
