// The table of worker job kinds (see worker_jobs.hpp).
#include "cic/run/worker_jobs.hpp"

#include <memory>
#include <stdexcept>

#include "cic/io/settings_io.hpp"
#include "cic/sim/job_text.hpp"
#include "cic/experiments/hypergp/model.hpp"

namespace cic::app {

std::map<std::string, JobHandler> make_worker_job_kinds(const WorkerContext& context) {
    std::map<std::string, JobHandler> kinds;
    // genotype -> fitness
    kinds["hypergp"] = hypergp::make_job_handler([context]() {
        if (!context.settings_text.empty()) return io::read_settings_string(context.settings_text, "settings from rank 0");
        if (context.settings_file.empty()) throw std::invalid_argument("hypergp jobs need `cic worker --settings FILE`");
        return io::read_settings(context.settings_file);
    });
    kinds["sine"] = &sim::run_sine_job;   // robot + SimConfig + sine joints -> fitness reply
    kinds["gait"] = &sim::run_gait_job;   // robot + SimConfig + gait spec -> fitness reply
    kinds["cpg"] = &sim::run_cpg_job;     // robot + SimConfig + CPG weights -> fitness reply
    return kinds;
}

std::string dispatch_worker_job(const std::map<std::string, JobHandler>& kinds, const std::string& job) {
    const std::size_t eol = job.find('\n');
    const std::string kind = job.substr(0, eol);
    const std::string body = eol == std::string::npos ? std::string() : job.substr(eol + 1);
    auto it = kinds.find(kind);
    if (it == kinds.end()) throw std::invalid_argument("worker: unknown job kind '" + kind + "'");
    return it->second(body);
}

} // namespace cic::app
