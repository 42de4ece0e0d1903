#pragma once
// The job kinds a `cic worker` process serves. A job is text whose first line
// is its kind; the rest (the body) goes to that kind's handler, whose return
// value is the reply. To add a kind, add one line in make_worker_job_kinds()
// (src/run/worker_jobs.cpp).
#include <functional>
#include <map>
#include <string>

namespace cic::app {

struct WorkerContext {
    std::string settings_file;   // `cic worker --settings FILE` (may be empty)
    // The effective settings as XML text, for workers that cannot read rank 0's
    // run folder (MPI ranks on other machines). When set, it wins over settings_file.
    std::string settings_text;
};

using JobHandler = std::function<std::string(const std::string& body)>;

// Built once per worker process; handlers may keep state (e.g. settings read once).
std::map<std::string, JobHandler> make_worker_job_kinds(const WorkerContext& context);

// Splits off the first line and calls its handler; an unknown kind throws
// std::invalid_argument naming it.
std::string dispatch_worker_job(const std::map<std::string, JobHandler>& kinds, const std::string& job);

} // namespace cic::app
