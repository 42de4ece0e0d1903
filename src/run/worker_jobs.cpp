// The job kinds of a worker process (see worker_jobs.hpp).
#include "cic/run/worker_jobs.hpp"

#include <stdexcept>

namespace cic::run {

std::map<std::string, JobHandler> make_worker_job_kinds(const WorkerContext& context) {
    return experiments::make_job_handlers(context);
}

std::string dispatch_worker_job(const std::map<std::string, JobHandler>& kinds, const std::string& job) {
    const std::size_t eol = job.find('\n');
    const std::string kind = job.substr(0, eol);
    const std::string body = eol == std::string::npos ? std::string() : job.substr(eol + 1);
    auto it = kinds.find(kind);
    if (it == kinds.end()) throw std::invalid_argument("worker: unknown job kind '" + kind + "'");
    return it->second(body);
}

} // namespace cic::run
