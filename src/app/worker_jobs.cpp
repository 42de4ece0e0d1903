// The table of worker job kinds (see worker_jobs.hpp).
#include "cic/app/worker_jobs.hpp"

#include <chrono>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>

#include "cic/io/settings_io.hpp"
#include "cic/sim/job_text.hpp"
#include "experiments/hypergp/model.hpp"

namespace cic::app {

namespace {

// Test-only: "sleep" + seconds; lets tests make a job that hangs past a timeout.
std::string sleep_job(const std::string& body) {
    const double seconds = std::stod(body);
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    return "slept";
}

// The "hypergp" kind from settings text (MPI ranks): the same work as
// hypergp::make_job_handler, with the model read once, on the first job.
JobHandler hypergp_from_text(const std::string& settings_text) {
    auto model = std::make_shared<std::optional<hypergp::Model>>();
    return [model, settings_text](const std::string& body) {
        if (!*model)
            *model = hypergp::Model::from_settings(io::read_settings_string(settings_text, "settings from rank 0"));
        return hypergp::reply(hypergp::run(**model, hypergp::parse_job_body(body)));
    };
}

} // namespace

std::map<std::string, JobHandler> make_worker_job_kinds(const WorkerContext& context) {
    std::map<std::string, JobHandler> kinds;
    // genotype -> fitness
    kinds["hypergp"] = context.settings_text.empty() ? hypergp::make_job_handler(context.settings_file)
                                                     : hypergp_from_text(context.settings_text);
    kinds["sine"] = &sim::run_sine_job;   // robot + SimConfig + sine joints -> fitness reply
    kinds["sleep"] = &sleep_job;
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
