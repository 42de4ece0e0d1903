#pragma once
// Evaluation in separate worker processes, talking over pipes.
// Separate processes are how cic gets bit-identical physics in parallel: ODE's
// QuickStep uses process-global random state (see README, "Determinism").
// A worker that crashes or hangs past the timeout is replaced; its job is
// retried, then reported failed. The run goes on.
#include <functional>
#include <string>
#include <vector>

#include "cic/core/job_runner.hpp"

namespace cic {

struct PoolOptions {
    int workers = 1;                    // >= 1
    std::vector<std::string> argv;      // command that starts one worker (argv[0] = executable path)
    double timeout_seconds = 120.0;     // per job
    int retries = 1;                    // extra attempts after a crash or hang
    // Asked about every 50 ms while a batch runs (e.g. Python's Ctrl-C check);
    // true ends every worker at once and run() throws cic::Interrupted. The
    // next run() starts fresh workers.
    std::function<bool()> interrupted = {};
};

// JobResult is declared in job_runner.hpp.

class ProcessPool : public JobRunner {
public:
    explicit ProcessPool(PoolOptions options);   // starts the workers; throws std::runtime_error
    ~ProcessPool() override;                     // ends them
    ProcessPool(const ProcessPool&) = delete;
    ProcessPool& operator=(const ProcessPool&) = delete;

    // Runs every job, results in job order. Jobs are handed to free workers in order.
    std::vector<JobResult> run(const std::vector<std::string>& jobs) override;

    int workers() const override;
    std::vector<std::string> take_notes() override;
    int restarts() const;                        // workers replaced so far
    std::vector<int> pids() const;               // for tests (kill one)

private:
    struct Impl;
    Impl* impl_;
};

// The worker's side: reads framed jobs from in_fd, answers each with handler(job)
// on out_fd, until end of input. A handler exception is sent back as a job error.
// Returns the process exit code to use.
int serve_worker(int in_fd, int out_fd, const std::function<std::string(const std::string&)>& handler);

} // namespace cic
