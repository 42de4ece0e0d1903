// The `cic` command line: options of the main job, subcommand registration,
// and the mapping of errors to exit codes (0 ok, 1 run failure, 2 bad input).
#include "cic/cli/cli.hpp"

#include <CLI/CLI.hpp>

#include <iostream>
#include <optional>

#include "cic/cli/commands.hpp"
#include "help.hpp"
#ifdef CIC_HAVE_MPI
#include "cic/run/mpi_pool.hpp"
#endif
#include "cic/run/provenance.hpp"
#include "cic/core/error.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/run/main_job.hpp"
#include "cic/run/settings_lookup.hpp"

namespace cic::cli {

int main(int argc, char** argv) {
    CommandContext ctx;
    for (int i = 0; i < argc; ++i) ctx.command_line += (i ? " " : "") + std::string(argv[i]);
    run::MainJob o;
    CLI::App app{"cic: evolutionary robotics with HyperGP (hypercube-encoded genetic programming evolving "
                 "recurrent neural controllers for simulated modular robots), and symbolic regression.\n"
                 "Runs the experiment a settings file describes; each run gets a fresh folder OUTPUT/NAME-NNN "
                 "with the effective settings, a log, statistics and populations.",
                 "cic"};
    // Where this binary came from: version, commit, compiler, flags, libraries (provenance.hpp).
    app.set_version_flag("--version", run::build_text());
    app.add_option("--settings", o.settings_file, "settings XML file (see `cic settings --defaults`)");
    app.add_option("--set", o.sets, "override one setting, Section.key=value (repeatable), e.g. GP.tournament_size=7")
        ->allow_extra_args(false);
    auto seed = app.add_option("--seed", o.seed, "shortcut for --set Experiment.seed=N");
    app.add_option("--seeds", o.seeds,
                   "one run per seed, one after another in this process: A-B or a comma list (sweeps; "
                   "each run gets its own folder)")
        ->excludes(seed);
    app.add_option("--output", o.output, "shortcut for --set Experiment.outputDirectory=DIR");
    auto quiet = app.add_flag("--quiet,-q", ctx.quiet, "no progress output");
    app.add_flag("--verbose,-v", ctx.verbose, "more progress output")->excludes(quiet);
    app.require_subcommand(0, 1);
    app.fallthrough();

    Command root(&app);
    add_settings_command(root, ctx);
    add_simulate_command(root, ctx);
    add_worker_command(root, ctx);
    add_render_command(root, ctx);
    add_plot_command(root, ctx);
    add_compare_command(root, ctx);
    add_trace_command(root, ctx);
    add_sweep_command(root, ctx);
    add_assess_command(root, ctx);
    add_transfer_command(root, ctx);
    add_resume_command(root, ctx);
    add_export_command(root, ctx);
    add_verify_command(root, ctx);
    add_eval_command(root, ctx);
    add_report_command(root, ctx);
    add_robot_command(root, ctx);
#ifdef CIC_HAVE_VIEWER
    add_view_command(root, ctx);
#endif
    add_help_command(app, ctx);
    add_docs_commands(root, ctx);   // last: `cic man` / `cic completion` document every subcommand
    // The settings keys: the main job's help only (a subcommand lists its own options).
    app.footer(io::settings_key_listing());

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        if (const std::string hint = settings_file_hint(app, argc, argv); !hint.empty()) {
            std::cerr << "cic: error: " << hint << '\n';   // cic's hint alone, before CLI11 could say less
            return 2;
        }
        std::cerr << "cic: error: " << e.what() << near_misses(app, argc, argv) << "\nRun `cic --help` for the options.\n";
        return 2;
    } catch (const InputError& e) {   // thrown by a subcommand outside its guard
        std::cerr << "cic: error: " << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "cic: error: " << e.what() << '\n';
        return 1;
    }
    if (!app.get_subcommands().empty()) return ctx.exit_code;

    if (o.settings_file.empty()) {
        std::cerr << "cic: error: give --settings FILE (or a subcommand); run `cic --help` for the options\n";
        return 2;
    }
#ifdef CIC_HAVE_MPI
    // Under mpirun (docs/mpi.md): rank 0 runs the job below, the other ranks only
    // evaluate jobs it sends them; they never read the settings file or write a
    // file. A plain `cic` run (no launcher in the environment) never touches MPI,
    // and neither do subcommands (so `cic worker` children stay out of it).
    // The session outlives the job: its end tells the ranks to stop.
    std::optional<run::MpiSession> mpi;
    const int launch_size = run::mpi_launch_size();
    if (launch_size > 1 || launch_size < 0) {
        mpi.emplace();
        if (mpi->rank() > 0) return mpi->serve();
    }
#endif
    try {
        // NAME.xml not found as given: the installed (or source-tree) settings folder.
        o.settings_file = run::find_settings_file(o.settings_file).string();
        o.command_line = ctx.command_line;
        o.quiet = ctx.quiet;
        o.verbose = ctx.verbose;
        return run::run_main_job(o);
    } catch (const InputError& e) {
        std::cerr << "cic: error: " << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "cic: error: " << e.what() << '\n';
        return 1;
    }
}

} // namespace cic::cli
