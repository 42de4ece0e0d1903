#pragma once
// Something that runs text jobs somewhere else and hands back the replies:
// worker processes on this machine (ProcessPool) or MPI ranks on several
// machines (run::MpiPool). Evaluators use this interface, so they do not care
// where a job runs. A job is text; its reply is text (see run/worker_jobs.hpp).
#include <string>
#include <vector>

namespace cic {

struct JobResult {
    bool ok = false;
    std::string output;                 // the worker's reply when ok
    std::string error;                  // why not, when !ok
    int attempts = 0;
    std::vector<std::string> trouble;   // why each failed attempt failed (a retried job has some)
};

class JobRunner {
public:
    virtual ~JobRunner() = default;
    // Runs every job, results in job order (whatever order they finish in).
    virtual std::vector<JobResult> run(const std::vector<std::string>& jobs) = 0;
    // How many jobs can run at once.
    virtual int workers() const = 0;
    // Trouble not tied to a job since the last call (e.g. a worker replaced while idle).
    virtual std::vector<std::string> take_notes() { return {}; }
};

} // namespace cic
