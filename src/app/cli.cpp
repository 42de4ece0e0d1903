// The `cic` command line: options of the main job, subcommand registration,
// and the mapping of errors to exit codes (0 ok, 1 run failure, 2 bad input).
#include "cic/app/cli.hpp"
#include "cic/app/self_path.hpp"

#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <optional>

#include "cic/app/commands.hpp"
#ifdef CIC_HAVE_MPI
#include "cic/app/mpi_pool.hpp"
#endif
#include "cic/app/run.hpp"
#include "cic/app/run_folder.hpp"
#include "cic/app/settings_lookup.hpp"
#include "cic/core/error.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/io/xml.hpp"

namespace cic::app {
namespace {

namespace fs = std::filesystem;

struct MainOptions {
    std::string settings_file;
    std::vector<std::string> sets;
    std::string seed;     // kept as text: validated by the settings table like any other value
    std::string seeds;    // "A-B" or "A,B,C": one run per seed in this process
    std::string output;
};

// "3-7" -> 3 4 5 6 7; "1,5,9" -> 1 5 9. Each seed is then checked by the settings table.
std::vector<std::string> expand_seeds(const std::string& text) {
    std::vector<std::string> out;
    auto number = [&](const std::string& t) {
        if (t.empty() || t.find_first_not_of("0123456789") != std::string::npos || t.size() > 19)
            throw InputError("--seeds: '" + t + "' is not a seed; expected A-B or a comma list such as 1,5,9");
        return std::stoull(t);
    };
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const std::string item = text.substr(start, comma - start);
        const std::size_t dash = item.find('-');
        if (dash == std::string::npos) {
            out.push_back(std::to_string(number(item)));
        } else {
            const auto a = number(item.substr(0, dash)), b = number(item.substr(dash + 1));
            if (b < a || b - a >= 100000)
                throw InputError("--seeds: range '" + item + "' must go up and hold at most 100000 seeds");
            for (auto v = a; v <= b; ++v) out.push_back(std::to_string(v));
        }
        start = comma + 1;
    }
    return out;
}

std::string command_line(int argc, char** argv) {
    std::string s;
    for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
    return s;
}

// The main job. Everything that can be wrong with the input is checked before
// anything is written.
int run_main_job(const MainOptions& o, const CommandContext& ctx, int argc, char** argv) {
    std::vector<std::string> overrides = o.sets;
    if (!o.seed.empty()) overrides.push_back("Experiment.seed=" + o.seed);
    if (!o.output.empty()) overrides.push_back("Experiment.outputDirectory=" + o.output);
    io::Settings settings = io::load_settings(o.settings_file, overrides);
    settings.experiment.name = run_name(settings);
    PreparedRun prepared = prepare_run(std::move(settings));   // every input checked: nothing written yet
    const io::Settings& s = prepared.settings;
    const std::string effective = io::write_settings(s);

    const fs::path run_dir = create_run_folder(s.experiment.output_directory, s.experiment.name);
    io::xml::write_file_atomically(run_dir / "settings.xml", effective);
    {
        std::ofstream log(run_dir / "run.log");
        log << "cic " << CIC_VERSION << "\ncommand: " << command_line(argc, argv) << "\nsettings: "
            << o.settings_file << " (effective settings in settings.xml)\n";
        if (!log) throw std::runtime_error("cannot write " + (run_dir / "run.log").string());
    }
    if (!ctx.quiet) std::cerr << "cic: run folder " << run_dir.string() << '\n';

    RunOptions run;
    run.run_dir = run_dir;
    run.quiet = ctx.quiet;
    run.verbose = ctx.verbose;
    run.worker_executable = self_exec_path();
    return run_experiment(std::move(prepared), run);
}

} // namespace

int main(int argc, char** argv) {
    CommandContext ctx;
    MainOptions o;
    CLI::App app{"cic: evolutionary robotics with HyperGP (hypercube-encoded genetic programming evolving "
                 "recurrent neural controllers for simulated modular robots), and symbolic regression.\n"
                 "Runs the experiment a settings file describes; each run gets a fresh folder OUTPUT/NAME-NNN "
                 "with the effective settings, a log, statistics and populations.",
                 "cic"};
    app.set_version_flag("--version", std::string("cic ") + CIC_VERSION);
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
    app.footer(io::settings_key_listing());
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
#ifdef CIC_HAVE_VIEWER
    add_view_command(root, ctx);
#endif
    add_docs_commands(root, ctx);   // last: `cic man` / `cic completion` document every subcommand

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "cic: error: " << e.what() << "\nRun `cic --help` for the options.\n";
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
    std::optional<MpiSession> mpi;
    const int launch_size = mpi_launch_size();
    if (launch_size > 1 || launch_size < 0) {
        mpi.emplace();
        if (mpi->rank() > 0) return mpi->serve();
    }
#endif
    try {
        // NAME.xml not found as given: the installed (or source-tree) settings folder.
        o.settings_file = find_settings_file(o.settings_file).string();
        if (o.seeds.empty()) return run_main_job(o, ctx, argc, argv);
        const auto seeds = expand_seeds(o.seeds);
        {   // check the settings for every seed before the first run writes anything
            std::vector<std::string> overrides = o.sets;
            if (!o.output.empty()) overrides.push_back("Experiment.outputDirectory=" + o.output);
            for (const auto& sd : seeds) {
                overrides.push_back("Experiment.seed=" + sd);
                prepare_run(io::load_settings(o.settings_file, overrides));
                overrides.pop_back();
            }
        }
        int rc = 0;
        for (const auto& sd : seeds) {
            MainOptions one = o;
            one.seed = sd;
            const int r = run_main_job(one, ctx, argc, argv);
            if (r == 130 || r == 143) return r;   // interrupted: stop the sweep
            if (rc == 0) rc = r;
        }
        return rc;
    } catch (const InputError& e) {
        std::cerr << "cic: error: " << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "cic: error: " << e.what() << '\n';
        return 1;
    }
}

} // namespace cic::app
