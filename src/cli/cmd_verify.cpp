// `cic verify RUN`: replay everything the run's last checkpoint holds and say
// each stored value that the replay does not give (cic/run/verify_run.hpp).
#include <memory>

#include "cic/cli/command_guard.hpp"
#include "cic/cli/commands.hpp"
#include "cic/run/verify_run.hpp"

namespace cic::cli {

void add_verify_command(Command& app, CommandContext& ctx) {
    struct Options {
        std::string run;
    };
    auto opts = std::make_shared<Options>();
    Command cmd = app.subcommand("verify", "Replay every individual, elite and stored best of a run's last "
                                           "checkpoint and check it against the run folder; each value that does "
                                           "not replay bit for bit is said (exit 0 only when all agree)");
    cmd.option("run", opts->run, "the run folder (holding settings.xml and population.xml)").required();
    cmd.on_run([opts, &ctx] {
        run_guarded(ctx, "verify", [&] { return run::verify_run(opts->run, ctx.quiet); });
    });
}

} // namespace cic::cli
