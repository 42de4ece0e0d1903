#pragma once
// The complete, typed settings of one run: the plain config structs of every
// layer plus the experiment and control sections. Read, written, schema'd and
// documented from one table (settings_table.hpp).
#include <cstdint>
#include <map>
#include <utility>
#include <string>
#include <vector>

#include "cic/gp/config.hpp"
#include "cic/nn/config.hpp"
#include "cic/sim/config.hpp"

namespace cic::io {

struct ExperimentConfig {
    // An experiment type's name (experiment_types.hpp); see the inference in settings_read.
    std::string type = "hypergp";
    // The registered search that drives the run (search_names.hpp); auto: the one the other keys imply.
    std::string search = "auto";
    std::uint64_t seed = 1;
    std::string output_directory = "runs";
    int workers = 0;                 // 0 = one per core
    int checkpoint_interval = 1;     // generations between population files
    double worker_timeout = 120.0;   // s before a hung worker is replaced
    std::string name;                // run name; output folder is output_directory/name-NNN
};

struct ControlConfig {
    int maximum_iterations = 50;
    double minimum_fitness = 50.0;
    std::string population_load_from;    // populationXmlLoadFrom
    bool plot = false;                   // useMatlabPlot -> our gnuplot output
    bool autonomous = true;              // isAutonomousExperiment; 0 shows the best at the end
};

// How the fitnesses of several bodies make one (Simulator.bodiesAggregate).
enum class BodiesAggregate { Mean, Min };

struct RobotConfig {
    int robot_type = 1;                  // 0, 1, 2 (R0, R1, R2)
    std::string robot_file;              // overrides robot_type when set
    bool generate_povray = false;        // generatePovrayFiles
    // Evolving for transfer (issue 55; docs/hypergp.md, "Evolving for
    // transfer"). The defaults keep one body for the whole run.
    // Several bodies in one fitness: each genotype is scored on the robot and
    // on each of these, and the fitnesses (eq. 7.1 after any penalty) combine
    // by bodies_aggregate.
    std::vector<std::string> extra_robot_files;
    BodiesAggregate bodies_aggregate = BodiesAggregate::Mean;
    // A growing robot: the bodies after the robot, in order; body k takes over
    // once the share grow_at[k-1] of the budget is spent (io/bodies.hpp).
    std::vector<std::string> grow_robot_files;
    std::vector<double> grow_at;
};

// Settings of the symbolic-regression experiment (thesis 6.2.1); plain data
// here, where the settings table can see it, used by experiments/symreg/.
struct SymregConfig {
    std::string target = "koza-1";   // benchmark name, or an expression over x (x0), y (x1) ...
    std::string data_file;           // CSV with header; last column is the target (overrides target)
    int samples = 20;                // n equidistant points (when not the benchmark's own)
    double range_min = -1.0;
    double range_max = 1.0;
    bool benchmark_sampling = true;  // use the named benchmark's own training set
    double hit_tolerance = 0.01;     // a point is a hit when |error| <= this
};

// The `gait` experiment (experiments/gait/): an open-loop gait per joint
// (sim::GaitSpec) whose parameters a pagmo2 optimiser tunes, a baseline for
// HyperGP at the same budget of evaluations (docs/baselines.md).
enum class GaitOptimizer { Cmaes, Xnes, Sade, Sepcmaes };
enum class GaitBounds { Clamp, Reflect };
// What the gait experiment's parameters drive: the open-loop sine gait, or the
// CPG of HyperGP's cpg substrate (its Neural.cpg* keys), weights tuned directly.
enum class GaitController { Sine, Cpg };
enum class GaitRestarts { None, Ipop };

struct GaitConfig {
    GaitOptimizer optimizer = GaitOptimizer::Cmaes;
    long evaluations = 2500;          // budget; whole generations only, never exceeded
    int population_size = 0;          // lambda; 0 = 4 + floor(3 ln n) (at least 7 for SADE)
    bool second_harmonic = false;     // adds b_j sin(4 pi f t + psi_j) per joint
    double sigma0 = 0.25;             // CMA-ES / xNES initial step, as a fraction of each parameter's range
    double frequency_min = 0.1;       // Hz, bounds of the shared frequency
    double frequency_max = 3.0;
    // How a sampled value outside its range is read: clamp (cic before this key
    // existed, so older runs replay alike) or reflect (settings/r1_gait.xml).
    GaitBounds bounds = GaitBounds::Clamp;
    GaitController controller = GaitController::Sine;
    // IPOP restarts of cmaes / xnes (experiments/gait/search.hpp, docs/baselines.md).
    GaitRestarts restarts = GaitRestarts::None;
    int restart_patience = 0;         // generations; 0 = 10 + ceil(30 n / lambda)
    double restart_tolerance = 1e-3;  // metres: a start whose best rises no more over the patience stagnates
    double restart_tol_x = 1e-6;      // unit box: every coordinate's spread below this = collapse; 0 = off
};

// MAP-Elites (ours, beyond the thesis; docs/quality-diversity.md): the search
// mode that fills a grid archive of elites over a behaviour descriptor instead
// of the GP loop or the gait experiment's pagmo optimiser.
struct MapElitesConfig {
    bool enabled = false;
    sim::Descriptor descriptor = sim::Descriptor::DutyFactor;
    int bins = 5;                  // per descriptor dimension
    double omni_range = 40.0;      // omni: the grid spans [-range, range] metres on x and on y
    int batch = 100;               // solutions evaluated together
    int initial = 100;             // made from nothing before any elite is varied
    std::string emitter = "auto";  // how elites are varied (emitter_names.hpp); auto = the family's own
    double sigma = 0.1;            // gait: the Gaussian mutation's standard deviation, in the unit box
    double line_sigma = 0.2;       // iso-line: the step along the line between two elites
    long evaluations = 2500;       // budget
    double qd_offset = -1.0;       // QD-score = sum over the elites of (fitness - qdOffset)
};

struct Settings {
    ExperimentConfig experiment;
    gp::GpConfig gp;
    gp::BloatConfig bloat;
    sim::SimConfig sim;
    RobotConfig robot;
    ControlConfig control;
    nn::NeuralConfig neural;
    SymregConfig symreg;
    GaitConfig gait;
    MapElitesConfig map_elites;
    // The keys of sections that registered experiment types bring
    // (settings_extension.hpp): "Section.key" -> canonical text, absent = default.
    std::map<std::string, std::string> extra;
    std::string source_file;             // where they were read from (empty = defaults)
    // Where each key given in a file or --set was written ("Section.key" ->
    // file, line; absent = its default), so that a check made later (a
    // budget, a grid) can point at the line (io::key_error).
    std::map<std::string, std::pair<std::string, int>> key_locations;
};

} // namespace cic::io
