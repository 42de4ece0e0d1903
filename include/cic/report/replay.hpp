#pragma once
// Replaying individuals for the viewer, POV-Ray export and traces. The
// simulation is re-run with the same simulator and settings the evaluation
// used, so the motion shown is the one that earned the fitness.
#include <cstdint>
#include <string>
#include <vector>

#include "cic/sim/recording.hpp"

namespace cic::app {

struct ReplayItem {
    std::string label;                               // e.g. "generation 12, individual 345"
    double stored_fitness = 0.0;                     // from the population file
    int generation = 0;
    std::uint64_t id = 0;
    sim::Recording recording;                        // frames at the requested fps
    std::vector<sim::TraceRow> trace;                // when trace was requested
    std::vector<std::vector<double>> raw_outputs;    // per trace row: raw network outputs
    double replayed_fitness = 0.0;                   // the run's score (after any oscillation penalty)
    double raw_fitness = 0.0;                        // eq. 7.1 alone: what every method is compared on
    int centre_body = 0;                             // body of the robot's centre module
    std::vector<std::string> joint_names;            // actuated joints in controller order; empty = "j0", "j1", ...
};

// Individuals from a run folder (its latest population file) or a population
// XML: `individual` is "best" (then the best `count`, best first) or an id.
// Implemented by the HyperGP experiment wiring (src/report/replay.cpp).
std::vector<ReplayItem> replay(const std::string& run_dir_or_population, const std::string& individual, int count,
                               double fps, bool trace);

} // namespace cic::app
