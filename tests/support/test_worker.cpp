// cic_test_worker: a worker for ProcessPool tests that speaks cic's wire
// format (core/process_pool.hpp) and runs the real sine evaluation, plus two
// job kinds that only tests need, so the production `cic worker` carries none:
//   "hang"          never answers (a job that outlives the timeout);
//   "once\nMARKER"  the first attempt writes its pid to MARKER and then hangs,
//                   so a test can kill exactly the worker running it; a retry
//                   finds MARKER and answers "retried".
#include <chrono>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>

#include <unistd.h>

#include "cic/core/process_pool.hpp"
#include "cic/sim/job_text.hpp"

namespace {

[[noreturn]] void hang() {
    for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
}

std::string handle(const std::string& job) {
    const std::size_t eol = job.find('\n');
    const std::string kind = job.substr(0, eol);
    const std::string body = eol == std::string::npos ? std::string() : job.substr(eol + 1);
    if (kind == "sine") return cic::sim::run_sine_job(body);
    if (kind == "hang") hang();
    if (kind == "once") {
        if (std::filesystem::exists(body)) return "retried";
        const std::string temp = body + ".tmp";
        std::ofstream(temp) << ::getpid() << '\n';
        std::filesystem::rename(temp, body);   // the test never sees a half-written pid
        hang();
    }
    throw std::invalid_argument("test worker: unknown job kind '" + kind + "'");
}

} // namespace

int main() {
    return cic::serve_worker(0, 1, handle);
}
