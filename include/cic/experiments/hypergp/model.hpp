#pragma once
// One HyperGP evaluation (thesis 5.1.5): genotype -> the controller that
// Neural.substrate names (network, CPG or gait; controller.hpp) -> ODE
// simulation -> fitness (eq. 7.1), with the optional oscillation penalty. The same code runs in-process, in worker processes and
// in replays, so a replayed fitness equals the stored one.
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>

#include "cic/gp/config.hpp"
#include "cic/io/settings.hpp"
#include "cic/sim/evaluate.hpp"
#include "cic/sim/job_text.hpp"
#include "cic/experiments/hypergp/controller.hpp"
#include "cic/experiments/hypergp/neural_controller.hpp"

namespace cic::hypergp {

// Immutable inputs shared by every evaluation of a run.
struct Model {
    sim::RobotSpec robot;
    sim::SimConfig sim;
    nn::NeuralConfig neural;
    // Several bodies in one fitness (Simulator.extraRobotFiles; bodies.hpp):
    // the bodies scored beside `robot`, and how their fitnesses make one.
    std::vector<sim::RobotSpec> extra_robots;
    io::BodiesAggregate aggregate = io::BodiesAggregate::Mean;
    // A growing robot (Simulator.growRobotFiles): the bodies after `robot`.
    std::vector<sim::RobotSpec> grow_robots;

    // The robot file if set, otherwise the robot_type preset with useMiddleLegs;
    // the other bodies from their files.
    static Model from_settings(const io::Settings& s);
    // This model on body `body` of a growing robot (0 = `robot`): its robot is
    // that body. Throws std::out_of_range past the last body.
    Model on_body(std::size_t body) const;
};

struct Outcome {
    double fitness = 0.0;           // after the penalty; failure_fitness when the physics failed
    double distance_fitness = 0.0;  // eq. 7.1 before any penalty
    bool failed = false;
    std::string failure;
    std::size_t synapses = 0;       // the controller's connections (controller.hpp)
    sim::EvalResult result;         // recording / trace when asked for
    ControlRecord control;          // raw outputs and commands when asked for
    // Several bodies (Model::extra_robots): each body's fitness, the robot
    // first; `fitness` is their aggregate, the other fields the robot's.
    std::vector<double> body_fitness;
};

// Every input a HyperGP run reads, checked before the run starts: the robot
// (file or preset) with at least one joint whose physics runs its first step
// (check_first_step), and a substrate within the limits (core/limits.hpp).
// Throws cic::InputError naming the file or key.
void check_inputs(const io::Settings& s);

// Throws cic::InputError (naming `where`) with the reason when one control step
// of a controller holding every joint at 0 fails: physics that cannot start.
void check_first_step(const sim::RobotSpec& robot, const sim::SimConfig& config, const std::string& where);

Outcome run(const Model& m, const tree::Forest& genotype, const sim::EvalOptions& options = {},
            bool record_control = false);
// With the genotype's direct offsets (gp::Individual::direct; Neural.directOffsets), empty for none.
Outcome run(const Model& m, const tree::Forest& genotype, std::span<const double> offsets,
            const sim::EvalOptions& options = {}, bool record_control = false);

// Offset-HybrID's genes (Neural.directOffsets): one offset per joint, in
// [-kOffsetLimit, kOffsetLimit] (gait_substrate.hpp), stepped by
// Neural.offsetSigma with probability Neural.offsetRate; none when off.
gp::DirectGenes direct_offset_genes(const Model& m);
// One genotype's offsets against the model's genes: none without
// Neural.directOffsets, else one per joint, each finite within +-limit.
// Throws cic::InputError "WHO: ..." (with `file`, when given).
void check_offsets(const Model& m, std::span<const double> offsets, const std::string& who,
                   const std::string& file = {});

// Worker protocol: the job body is the trees, one S-expression per line, then,
// with direct offsets, a line "offsets D1 D2 ..." (shortest round-trip
// decimals: the exact doubles), on a growing robot's later bodies a line
// "body K" (K >= 1, Model::on_body; absent = body 0), and, for MAP-Elites, a
// last line "descriptor NAME"; the reply is sim's evaluation
// reply (sim/job_text.hpp), the same for every runner, with the descriptor's
// values when one was asked for.
struct Job {
    tree::Forest genotype;
    std::vector<double> offsets;
    std::size_t body = 0;
    sim::Descriptor descriptor = sim::Descriptor::None;
};
std::string job_body(const tree::Forest& genotype, sim::Descriptor descriptor = sim::Descriptor::None,
                     std::span<const double> offsets = {}, std::size_t body = 0);
Job parse_job_body(const std::string& body);   // throws std::invalid_argument
// The reply of an evaluation of `m`'s robot: eq. 7.1's terms come from the walk,
// whatever score the fitness is.
sim::EvalReply to_reply(const Model& m, const Outcome& o, std::vector<double> descriptor = {});

// A fitness other than eq. 7.1 for the same simulation (a registered type's
// own, examples/plugin): called for each evaluation that did not fail, with
// the run's model and settings; a non-finite value scores the evaluation as failed.
using Score = std::function<double(const Model&, const io::Settings&, const Outcome&)>;

// What a Score reads of the walk beyond the centre's position at the delayed
// start and at the end (Outcome::result.start/end, always there). The
// simulator records only what is asked, so a score pays only for what it reads.
struct WalkNeeds {
    bool trace = false;    // result.trace: per control step the time, the centre's path, joint angles and targets
    bool contacts = false; // with trace, each row's feet_on_ground; and result.module_ground_steps (duty factors)
};

// The simulation options that record what `needs` (and the descriptor) ask.
sim::EvalOptions options_for(const WalkNeeds& needs, sim::Descriptor descriptor = sim::Descriptor::None);

// Applies a type's score to an outcome that did not fail (a non-finite score
// fails it with the failure fitness); leaves eq. 7.1 when `score` is empty.
// The worker jobs and every replay (view, assess, trace, Python's simulate) call it.
void apply_score(Outcome& o, const Score& score, const Model& m, const io::Settings& s);

// One job as a worker evaluates it, `m` being the model of its body
// (Model::on_body(job.body)): run, scored by `score`, and with extra bodies
// on each of them alike, the fitnesses aggregated (bodies.hpp). Replays of
// one body call run() instead.
Outcome evaluate_job(const Model& m, const io::Settings& s, const Job& job, const Score& score = {},
                     const WalkNeeds& needs = {});

// The "hypergp" job kind of a worker (and a registered type's, with its own
// `score`): `settings` is called once, on the first job (a worker reads the
// run's settings.xml; an MPI rank parses rank 0's text), then each job's
// genotype is evaluated.
std::function<std::string(const std::string&)> make_job_handler(std::function<io::Settings()> settings,
                                                                 Score score = {}, WalkNeeds needs = {});

} // namespace cic::hypergp
