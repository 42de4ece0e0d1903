#pragma once
// The genotype a run folder holds as its best, as `cic assess` replays it:
// the latest checkpoint's best individual (HyperGP), a gait run's champion,
// a MAP-Elites archive's fittest elite. One reader for `transfer`, Python's
// `read_run` (run::read_run_best) and whoever needs a run's best genotype.
#include <string>
#include <vector>

#include "cic/io/settings.hpp"
#include "cic/sim/robot.hpp"
#include "cic/tree/tree.hpp"

namespace cic::report {

// Which genotype of a Switch-HybrID run past its hand-over: the direct gait
// it now evolves (Latest), or the best of its last HyperGP generation
// (HyperGP: the genotype that does not grow with the robot). Other runs have one.
enum class SwitchPhase { Latest, HyperGP };

struct RunGenotype {
    std::string run;                // as given
    io::Settings settings;          // the run's own
    sim::RobotSpec robot;           // the robot it was evolved on (a growing run's current body)
    std::string robot_file;         // that robot's file; empty for a preset (settings' robot_type)
    tree::Forest trees;             // HyperGP trees; empty for a direct gait
    std::vector<double> offsets;    // Offset-HybrID's direct genes beside the trees; empty otherwise
    std::vector<double> gait;       // a direct gait as the run stored it (its layout); empty beside trees
    double stored_fitness = 0;      // as the run stored it
    int generation = 0;             // as stats.csv counts (a gait phase after Switch-HybrID's GP phase)
    std::string what;               // "HyperGP trees (gait substrate)", "direct gait (sepcmaes)", ...
};

// Checked against the run's settings (io::check_compatible). Throws
// cic::InputError naming the folder or file.
RunGenotype read_run_genotype(const std::string& run_dir, SwitchPhase phase = SwitchPhase::Latest);

} // namespace cic::report
