#pragma once
// Replaying individuals for the viewer, POV-Ray export and traces. The
// simulation is re-run with the same simulator and settings the evaluation
// used, so the motion shown is the one that earned the fitness.
#include <array>
#include <functional>
#include <span>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "cic/io/settings.hpp"
#include "cic/sim/evaluate.hpp"
#include "cic/sim/recording.hpp"
#include "cic/tree/tree.hpp"

namespace cic::report {

struct ReplayItem {
    std::string label;                               // e.g. "generation 12, individual 345"
    double stored_fitness = 0.0;                     // from the population file
    int generation = 0;                              // a gait run's: the one its best was found in
    std::uint64_t id = 0;                            // the individual's id; a MAP-Elites elite's cell number
    bool elite = false;                              // an archive's elite: the label names its cell
    std::string who;                                 // what an overlay names; empty = the individual's id
    sim::Recording recording;                        // frames at the requested fps
    std::vector<sim::TraceRow> trace;                // when trace was requested
    std::vector<std::vector<double>> raw_outputs;    // per trace row: raw network outputs
    double replayed_fitness = 0.0;                   // the run's score (after any oscillation penalty)
    double raw_fitness = 0.0;                        // eq. 7.1 alone: what every method is compared on
    int centre_body = 0;                             // body of the robot's centre module
    std::vector<std::string> joint_names;            // actuated joints in controller order; empty = "j0", "j1", ...
    // Eq. 7.1's two terms, m: the walk along the preferred axis and the elevation gained.
    double distance = 0.0, elevation = 0.0;
    // Eq. 7.1's measure: the preferred axis (0 = x, 1 = y) and the centre at
    // the delayed start and at the end, m.
    int preferred_axis = 1;
    std::array<double, 3> measured_from{}, measured_to{};
    // With trace: each branch end (sim::branch_ends: the feet) and the fraction
    // of the time from the delayed start on that it touched the ground.
    std::vector<std::string> foot_names;
    std::vector<double> duty_factors;
    // A MAP-Elites elite's behaviour descriptor as the replay gives it (verify.hpp); empty otherwise.
    std::vector<double> descriptor;
};

// Eq. 7.1's two terms of an evaluation, m: the walk along the robot's
// preferred axis and the elevation gained by its centre module.
std::pair<double, double> eq71_terms(const sim::RobotSpec& robot, const sim::EvalResult& result);

// Sets the item's distance and elevation from the evaluation, and with
// recorded ground contacts (EvalOptions::record_ground) its feet's duty factors.
void fill_walk(ReplayItem& item, const sim::RobotSpec& robot, const sim::EvalResult& result);

// One HyperGP genotype (with Offset-HybrID's offsets, or none) walked under
// `settings` (their robot), scored as the run's type scores it and recorded:
// what replay() does for each individual it picks.
ReplayItem replay_genotype(const io::Settings& settings, const tree::Forest& genotype,
                           std::span<const double> offsets, double fps, bool trace);
// One gait vector of the settings' gait (their layout, unit box), walked and recorded.
ReplayItem replay_gait_vector(const io::Settings& settings, const std::vector<double>& x, double fps, bool trace);

// Individuals from a run folder (its latest population file) or a population
// XML: `individual` is "best" (then the best `count`, best first) or an id. In
// a MAP-Elites run (an archive) it is "best" (the fittest `count` elites) or
// "cell:I,J,..." / "cell:N" (one elite, by its bins or its cell's number).
// Implemented by the HyperGP experiment wiring (src/report/replay.cpp).
std::vector<ReplayItem> replay(const std::string& run_dir_or_population, const std::string& individual, int count,
                               double fps, bool trace);

// The best individual a search's own checkpoint holds (a search registered from
// outside cic's three checkpoint files: search/search.hpp, SearchKind::best):
// a gait vector, or for a search of trees its trees.
struct CheckpointBest {
    std::vector<double> x;   // a gait vector in the unit box; beside trees, their direct genes (Neural.directOffsets)
    double fitness = 0;      // as the run stored it
    int generation = 0;      // where the run found it (or its last generation)
    std::string who;         // "best (1+8)-ES gait"
    tree::Forest trees;      // a search of trees: the genotype, replayed as the run's type scores it
};
using CheckpointBestReader = std::function<CheckpointBest(const io::Settings&, const std::string& file)>;
// replay() (view, assess, trace, render, export's terms) reads checkpoints
// whose root element is `root` with `reader` and replays the gait it gives.
// Throws std::invalid_argument for a root of cic's own files or one taken.
void register_checkpoint_reader(std::string root, CheckpointBestReader reader);
// The reader registered for the root element of `file`, or nullptr (no such
// registration, or not an XML file: cic's own readers then say what is wrong).
const CheckpointBestReader* checkpoint_reader_for(const std::string& file);
// What `reader` gives for `file`, checked against the settings: a gait vector of
// their gait's length, or (a HyperGP-family type) their number of trees with the
// offsets Neural.directOffsets asks for. Throws cic::InputError naming the file.
CheckpointBest read_checkpoint_best(const CheckpointBestReader& reader, const io::Settings& s, const std::string& file);

} // namespace cic::report
