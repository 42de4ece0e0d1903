#pragma once
// The centre's path seen from above (`cic plot --path`): where a replayed
// individual walked, with eq. 7.1's preferred axis marked, for one or several
// runs, or for the best run of each configuration of a study.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "cic/report/plot.hpp"
#include "cic/report/replay.hpp"

namespace cic::report {

struct CentrePath {
    std::string label;
    std::vector<std::array<double, 2>> xy;   // the centre module on the ground plane, m, in time order
    std::array<double, 2> measured_from{};   // eq. 7.1's start (the delayed start) and end
    std::array<double, 2> measured_to{};
    int preferred_axis = 1;                  // 0 = x, 1 = y
    double distance = 0.0;                   // eq. 7.1's walk along the preferred axis, m
    double fitness = 0.0;                    // the replay's fitness
};

// The centre's path of a replay: its trace's centre column when traced, else
// the centre body in each recorded frame. Throws std::invalid_argument when
// the item has neither.
CentrePath centre_path(const ReplayItem& item, std::string label);

// The run a study shows for a configuration: the highest best_ever (else
// final_best) among its runs; nullptr when it has none.
const StudyRun* best_run_of(const StudyGroup& group);

// The best individual of each run folder, or of the best run (highest
// best_ever, else final_best) of each configuration of one study folder,
// replayed with a trace. Labels: the run folder's name, or "CONFIG (seed S)".
// Throws cic::InputError for a study without a done run.
std::vector<CentrePath> best_paths(const std::vector<std::filesystem::path>& runs_or_study,
                                   bool include_unfinished = false);

// One figure, x against y with equal scales: each path with a circle at its
// start and a cross at its end, and an arrow along the first path's preferred
// axis from its eq. 7.1 start. Throws std::invalid_argument for no paths.
void plot_paths(const std::vector<CentrePath>& paths, const std::filesystem::path& out_file,
                const PlotOptions& options = {});

} // namespace cic::report
