#pragma once
// Plain-text forms of a robot, a SimConfig and an evaluation result, for
// sending evaluations to worker processes. Numbers are written as hexfloats
// so that they round-trip bit for bit.
#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "cic/core/job_runner.hpp"
#include "cic/sim/config.hpp"
#include "cic/sim/controller.hpp"
#include "cic/sim/cpg.hpp"
#include "cic/sim/evaluate.hpp"
#include "cic/sim/robot.hpp"

namespace cic::sim {

// Each reader consumes exactly what the matching writer wrote and throws
// std::invalid_argument on malformed text.
void write_robot_text(std::ostream& out, const RobotSpec& robot);
RobotSpec read_robot_text(std::istream& in);
void write_config_text(std::ostream& out, const SimConfig& cfg);
SimConfig read_config_text(std::istream& in);

std::string hexfloat(double v);        // "%a"
double parse_hexfloat(const std::string& s);   // also accepts decimal, "inf"

// The one reply of every evaluation job (sine, gait, hypergp), whether it ran in a
// worker process or on an MPI rank: fitness (exact), the behaviour descriptor
// when the job asked for one, eq. 7.1's two terms, failed flag, failure text.
struct EvalReply {
    double fitness = 0.0;
    std::vector<double> descriptor;   // the behaviour descriptor the job asked for (empty when failed)
    bool failed = false;
    std::string failure;   // the rest of the reply (may span lines)
    // Eq. 7.1's terms (walk_terms, sim/evaluate.hpp), whatever the fitness is made of
    // (a registered type may score otherwise): 0 when failed.
    double distance = 0.0, elevation = 0.0;
};
std::string format_eval_reply(const EvalReply& r);
// The reply of an evaluation of `robot`: its fitness, eq. 7.1's terms and `descriptor`.
EvalReply reply_of(const RobotSpec& robot, const EvalResult& r, std::vector<double> descriptor = {});
EvalReply parse_eval_reply(const std::string& text);
// A job's reply as a run scores it: the worker's reply when the job ran, else
// (its worker crashed or hung twice) a failed evaluation with `failure_fitness`
// and "worker: WHY". One rule for every evaluator (gait, HyperGP, Python's).
EvalReply reply_of(const JobResult& result, double failure_fitness);

// Job kind "sine": the first line is "sine", then robot, config and joints.
std::string make_sine_job(const RobotSpec& robot, const SimConfig& cfg,
                          const std::vector<SineJoint>& joints);
// Runs a "sine" job body (the text after the first line); returns the reply.
std::string run_sine_job(const std::string& body);

// Job kind "gait": the first line is "gait", then robot, config and the spec.
// With a descriptor the job ends with "descriptor NAME" and its reply carries
// that behaviour descriptor (MAP-Elites); the fitness is the same bits.
std::string make_gait_job(const RobotSpec& robot, const SimConfig& cfg, const GaitSpec& gait,
                          Descriptor descriptor = Descriptor::None);
// Runs a "gait" job body; returns the reply.
std::string run_gait_job(const std::string& body);

// Job kind "cpg": the first line is "cpg", then robot, config and the CPG's
// weights (sim/cpg.hpp). make_cpg_job validates the spec first.
std::string make_cpg_job(const RobotSpec& robot, const SimConfig& cfg, const CpgSpec& cpg,
                         Descriptor descriptor = Descriptor::None);
CpgSpec read_cpg_spec(std::istream& in);   // the part after robot and config
// Runs a "cpg" job body; returns the reply.
std::string run_cpg_job(const std::string& body);

} // namespace cic::sim
