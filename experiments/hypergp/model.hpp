#pragma once
// One HyperGP evaluation (thesis 5.1.5): genotype -> substrate network ->
// neural controller -> ODE simulation -> fitness (eq. 7.1), with the optional
// oscillation penalty. The same code runs in-process, in worker processes and
// in replays, so a replayed fitness equals the stored one.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "cic/io/settings.hpp"
#include "cic/sim/evaluate.hpp"
#include "experiments/hypergp/neural_controller.hpp"

namespace cic::hypergp {

// Immutable inputs shared by every evaluation of a run.
struct Model {
    sim::RobotSpec robot;
    sim::SimConfig sim;
    nn::NeuralConfig neural;

    // The robot file if set, otherwise the robot_type preset with useMiddleLegs.
    static Model from_settings(const io::Settings& s);
};

struct Outcome {
    double fitness = 0.0;           // after the penalty; failure_fitness when the physics failed
    double distance_fitness = 0.0;  // eq. 7.1 before any penalty
    bool failed = false;
    std::string failure;
    std::size_t synapses = 0;
    sim::EvalResult result;         // recording / trace when asked for
    ControlRecord control;          // raw outputs and commands when asked for
};

Outcome run(const Model& m, const tree::Forest& genotype, const sim::EvalOptions& options = {},
            bool record_control = false);

// Worker protocol: the job body is the trees, one S-expression per line; the
// reply is the fitness as a hex float (exact), a space, and 0/1 for failed.
std::string job_body(const tree::Forest& genotype);
tree::Forest parse_job_body(const std::string& body);
std::string reply(const Outcome& o);
struct Reply {
    double fitness = 0.0;
    bool failed = false;
};
Reply parse_reply(const std::string& text);

// The "hypergp" job kind of `cic worker --settings FILE`: reads the settings
// once, on the first job, then evaluates each job's genotype.
std::function<std::string(const std::string&)> make_job_handler(const std::string& settings_file);

} // namespace cic::hypergp
