#pragma once
// The job kinds a `cic worker` process (or an MPI rank) serves: those of every
// registered experiment type (experiments/registry.hpp) and sim's `sine`. A
// job is text whose first line is its kind; the rest (the body) goes to that
// kind's handler, whose return value is the reply. A type adds its kinds in
// its own registration, not here.
#include <map>
#include <string>

#include "cic/experiments/registry.hpp"

namespace cic::run {

using experiments::JobHandler;
using experiments::WorkerContext;

// Built once per worker process; handlers may keep state (e.g. settings read once).
std::map<std::string, JobHandler> make_worker_job_kinds(const WorkerContext& context);

// Splits off the first line and calls its handler; an unknown kind throws
// std::invalid_argument naming it.
std::string dispatch_worker_job(const std::map<std::string, JobHandler>& kinds, const std::string& job);

} // namespace cic::run
