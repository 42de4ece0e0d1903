// `cic worker --settings FILE`: serves evaluation jobs on stdin/stdout for a
// ProcessPool in the parent process (framed, see core/process_pool.hpp).
#include <unistd.h>

#include <memory>

#include "cic/cli/commands.hpp"
#include "cic/run/worker_jobs.hpp"
#include "cic/core/process_pool.hpp"

namespace cic::cli {

void add_worker_command(Command& app, CommandContext& ctx) {
    auto context = std::make_shared<experiments::WorkerContext>();
    Command cmd = app.subcommand("worker", "Serve evaluation jobs on stdin/stdout (started by cic itself)");
    cmd.option("--settings", context->settings_file, "Settings file of the run");
    cmd.hide();   // internal: hidden from --help
    cmd.on_run([context, &ctx] {
        // Frames go to the original stdout; anything else printed to stdout
        // (by a library, say) goes to stderr instead of corrupting the stream.
        const int out = ::dup(1);
        ::dup2(2, 1);
        const auto kinds = run::make_worker_job_kinds(*context);
        ctx.exit_code = serve_worker(0, out, [&kinds](const std::string& job) {
            return run::dispatch_worker_job(kinds, job);
        });
        ::close(out);
    });
}

} // namespace cic::cli
