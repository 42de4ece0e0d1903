// `cic resume RUN [--generations N | --until G] [--set K=V]...`: continue a run
// in its own folder (cic/run/resume.hpp).
#include <memory>

#include "cic/cli/command_guard.hpp"
#include "cic/cli/commands.hpp"
#include "cic/run/resume.hpp"

namespace cic::cli {

void add_resume_command(Command& app, CommandContext& ctx) {
    struct Options {
        std::string run;
        int generations = 0, until = 0;
        std::vector<std::string> sets;
    };
    auto opts = std::make_shared<Options>();
    Command cmd = app.subcommand("resume", "Continue a run in its own folder, as if it had never stopped: stats.csv "
                                           "and run.log grow, checkpoints are numbered on; more generations with "
                                           "--generations or --until (a gait run: --set Gait.evaluations=E)");
    cmd.option("run", opts->run, "the run folder (holding settings.xml and population.xml)").required();
    auto more = cmd.option("--generations", opts->generations, "this many generations more").positive();
    auto until = cmd.option("--until", opts->until, "until this many generations have been evaluated in all").positive();
    cmd.option("--set", opts->sets, "Section.key=value (repeatable): the budget, or keys that change no result such "
                                    "as Experiment.workers");
    cmd.on_run([opts, &ctx, more, until] {
        run_guarded(ctx, "resume", [&] {
            run::ResumeRequest r;
            r.run_dir = opts->run;
            if (more.count()) r.generations = opts->generations;
            if (until.count()) r.until = opts->until;
            r.sets = opts->sets;
            r.command_line = ctx.command_line;
            r.quiet = ctx.quiet;
            r.verbose = ctx.verbose;
            return run::resume_run(r);
        });
    });
}

} // namespace cic::cli
