#pragma once
// What the run loop needs from an experiment: an evaluator for genotypes and a
// way to describe results. Experiments are chosen by <Experiment><type>.
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

#include "cic/core/job_runner.hpp"
#include "cic/gp/evolution.hpp"
#include "cic/io/settings.hpp"

namespace cic::experiments {

struct Context {
    const io::Settings& settings;
    std::filesystem::path base_dir;          // relative paths in settings resolve against this
    std::filesystem::path settings_file;     // effective settings (worker processes read it)
    std::string worker_executable;           // the cic binary, for worker processes
    int workers = 1;                         // resolved (>= 1)
    // When set, evaluation jobs go to the runner this makes instead of worker
    // processes, and `workers` does not apply to them. The app sets it under
    // mpirun (MPI ranks, docs/mpi.md); experiments need not know where jobs run.
    std::function<std::unique_ptr<JobRunner>()> make_runner = {};
    // Where an experiment reports trouble that does not stop the run (a worker
    // replaced, a job retried or scored as failed): run.log and the console.
    std::function<void(const std::string&)> warn = [](const std::string&) {};
    // Worker processes ask it during a batch; true stops the batch
    // (core/process_pool.hpp PoolOptions::interrupted). Python's Ctrl-C.
    std::function<bool()> interrupted = {};
};

class Experiment {
public:
    virtual ~Experiment() = default;
    virtual gp::Evaluator& evaluator() = 0;
    // One line about an individual for logs and summary.txt (e.g. hits).
    virtual std::string describe(const gp::Individual& ind) const = 0;
    // Whether the best individual solved the task (symreg: every point a hit).
    virtual bool success(const gp::Individual&) const { return false; }
    // A line for run.log at the end of the session (e.g. how many evaluations
    // reused an earlier result); empty = nothing to say.
    virtual std::string session_note() const { return {}; }
    // Genes the genotype holds beside its trees (gp::GpConfig::direct): none
    // unless the experiment reads some (HyperGP-gait's Neural.directOffsets).
    virtual gp::DirectGenes direct_genes() const { return {}; }
    // A growing robot (Simulator.growRobotFiles, io/bodies.hpp): evaluate on
    // body `body` (0 = the robot) from now on. Only types whose settings may
    // grow (the hypergp family; settings validation refuses the others) are asked.
    virtual void use_body(std::size_t body) {
        if (body != 0) throw std::logic_error("this experiment type has one body");
    }
};

std::unique_ptr<Experiment> make_experiment(const Context& ctx);

// Where a robot experiment's evaluation jobs run: the context's runner (MPI
// ranks) when it has one, else `cic worker` processes, always, even for one
// worker: one path, so a crash or hang of an evaluation gives the same result
// whatever the worker count.
std::unique_ptr<JobRunner> make_job_runner(const Context& ctx);

// Loads and checks every input the experiment will read (robot, dataset),
// throwing cic::InputError with file and line; writes nothing. The run calls
// it before its folder exists, and `cic settings FILE` calls it too.
void check_inputs(const io::Settings& s);

} // namespace cic::experiments
