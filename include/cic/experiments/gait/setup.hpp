#pragma once
// The gait experiment's wiring: settings -> robot, simulator, encoding and
// optimiser; candidates -> "gait" jobs for the worker processes or MPI ranks
// (the same runners and reply as HyperGP, so fitness bits do not depend on
// where or on how many workers a candidate ran).
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cic/core/job_runner.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/settings.hpp"
#include "cic/sim/robot.hpp"
#include "cic/experiments/experiment.hpp"
#include "cic/gp/vector_map_elites.hpp"
#include "cic/sim/job_text.hpp"
#include "cic/experiments/gait/cpg_encoding.hpp"
#include "cic/experiments/gait/encoding.hpp"
#include "cic/experiments/gait/search.hpp"

namespace cic::gait {

struct Setup {
    sim::RobotSpec robot;
    sim::SimConfig sim;
    Encoding encoding;           // the sine gait's (Gait.controller = sine)
    std::optional<CpgEncoding> cpg;   // set when Gait.controller = cpg
    Optimizer optimizer = Optimizer::Cmaes;
    int population = 0;          // resolved (Gait.populationSize or the default)
    double sigma0 = 0.25;

    // Of the encoding Gait.controller chooses.
    std::size_t dimension() const { return cpg ? cpg->dimension() : encoding.dimension(); }
    std::unique_ptr<sim::Controller> controller(std::span<const double> x) const;
    // The unit-box point with the same controller, bit for bit (Encoding::in_box).
    std::vector<double> in_box(std::span<const double> x) const { return cpg ? cpg->in_box(x) : encoding.in_box(x); }
    // One line: the frequency and each joint's parameters, or the CPG's weights.
    std::string describe(std::span<const double> x) const;

    // The robot of the settings (file or preset with useMiddleLegs, as HyperGP
    // builds it). Throws cic::InputError for a robot that cannot be loaded.
    static Setup from_settings(const io::Settings& s);
};

Optimizer optimizer_of(io::GaitOptimizer o);

// The robot (with at least one joint) and the population size; writes nothing.
void check_inputs(const io::Settings& s);

// With a descriptor the reply carries it (sim/job_text.hpp).
std::string make_job(const Setup& setup, std::span<const double> x, sim::Descriptor descriptor = sim::Descriptor::None);

// Evaluates batches of unit-box points on the context's runner. A job that
// fails in the runner (its worker crashed or hung twice) scores the
// simulator's failure fitness, with a warning, as in HyperGP.
class Evaluator {
public:
    Evaluator(const experiments::Context& ctx, const Setup& setup);
    ~Evaluator();
    std::vector<double> operator()(const std::vector<std::vector<double>>& xs);
    // The same with each point's behaviour descriptor, for MAP-Elites: a
    // failed evaluation (physics or worker) is marked failed, not archived.
    std::vector<gp::Evaluation> described(const std::vector<std::vector<double>>& xs,
                                          sim::Descriptor descriptor = sim::Descriptor::DutyFactor);
    long failed() const { return failed_; }   // evaluations that failed (physics or worker)
    // Each point's whole reply (fitness, eq. 7.1's terms, descriptor); a job the
    // runner could not run scores the failure fitness. The Python bindings' path.
    std::vector<sim::EvalReply> replies(const std::vector<std::vector<double>>& xs, sim::Descriptor descriptor);

private:
    const Setup& setup_;
    std::function<void(const std::string&)> warn_;
    std::unique_ptr<JobRunner> runner_;
    long failed_ = 0;
};

} // namespace cic::gait
