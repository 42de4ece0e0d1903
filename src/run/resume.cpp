// `cic resume RUN` (resume.hpp): a run continued in its own folder.
#include "cic/run/resume.hpp"

#include <chrono>
#include <fstream>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/io/experiment_types.hpp"
#include "cic/io/archive_xml.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/io/xml.hpp"
#include "cic/run/provenance.hpp"
#include "cic/run/run.hpp"
#include "cic/run/self_path.hpp"
#include "cic/run/settings_diff.hpp"

namespace cic::app {
namespace {

namespace fs = std::filesystem;

} // namespace

int resume_run(const ResumeRequest& r) {
    const fs::path dir = fs::absolute(r.run_dir);
    const fs::path settings_file = dir / "settings.xml", checkpoint = dir / "population.xml";
    if (!fs::is_regular_file(settings_file) || !fs::is_regular_file(checkpoint))
        throw InputError("not a run folder with a checkpoint (settings.xml and population.xml): " + dir.string());
    if (r.generations && r.until) throw InputError("--generations and --until: give one of them");
    const io::Settings ran = io::read_settings(settings_file);
    io::Settings asked = io::load_settings(settings_file, r.sets);
    const bool gait = io::family_of(ran) == io::ExperimentFamily::Gait;
    const std::string where = checkpoint.string();

    if (ran.map_elites.enabled) {
        if (r.generations || r.until)
            throw InputError("a MAP-Elites run's budget is its evaluations: resume it with --set MapElites.evaluations=E");
        const io::ArchiveFile a = io::load_archive(checkpoint);
        if (asked.map_elites.evaluations <= a.evaluations)
            throw InputError(fmt::format("the run has spent {} of its {} evaluations; ask for more with "
                                         "--set MapElites.evaluations=E (E > {})",
                                         a.evaluations, asked.map_elites.evaluations, a.evaluations),
                             where);
    } else if (gait || ran.neural.switches()) {
        // Switch-HybrID's budget is Gait.evaluations too, over both phases.
        if (r.generations || r.until)
            throw InputError(gait ? "a gait run's budget is its evaluations: resume it with --set Gait.evaluations=E"
                                  : "a Switch-HybrID run's budget is its evaluations over both phases: resume it "
                                    "with --set Gait.evaluations=E");
        long spent = 0;
        if (io::is_gait_file(checkpoint)) {
            const io::GaitFile g = io::load_gait(checkpoint);
            spent = g.evaluations + (g.handover ? g.handover->evaluations : 0);
        } else {
            spent = io::load_population(checkpoint).state.evaluations;
        }
        if (asked.gait.evaluations <= spent)
            throw InputError(fmt::format("the run has spent {} of its {} evaluations; ask for more with "
                                         "--set Gait.evaluations=E (E > {})",
                                         spent, asked.gait.evaluations, spent),
                             where);
    } else {
        const io::PopulationFile loaded = io::load_population(checkpoint);
        const int done = loaded.population.generation + 1;   // generations evaluated
        if (loaded.population.best().fitness >= asked.control.minimum_fitness)
            throw InputError(fmt::format("the run reached Control.minimumFitness {} (best {}); to go on, raise it "
                                         "with --set Control.minimumFitness=F",
                                         asked.control.minimum_fitness, loaded.population.best().fitness),
                             where);
        if (r.until) asked.control.maximum_iterations = *r.until;
        if (r.generations) asked.control.maximum_iterations = done + *r.generations;
        if (asked.control.maximum_iterations <= done)
            throw InputError(fmt::format("the run has evaluated {} generation{} (Control.maximumIterations {}); ask "
                                         "for more with --generations N or --until G (G > {})",
                                         done, done == 1 ? "" : "s", asked.control.maximum_iterations, done),
                             where);
    }

    std::vector<std::string> refused;
    for (const auto& d : settings_differences(ran, asked, "the resume"))
        if (!is_budget_difference(d)) refused.push_back(d);
    if (!refused.empty()) {
        std::string text = fmt::format("cannot continue {} with other settings than it ran:", dir.string());
        for (const auto& d : refused) text += "\n  " + d;
        throw InputError(text + "\nresume changes only the budget (--generations, --until, Control.minimumFitness, Gait.evaluations, "
                                "MapElites.evaluations) and "
                                "keys that change no result (workers); start a new run for other settings",
                         settings_file.string());
    }

    asked.control.population_load_from = checkpoint.string();
    PreparedRun prepared = prepare_run(asked);   // the checkpoint parsed and checked against the settings
    io::Settings stored = prepared.settings;
    stored.control.population_load_from.clear();
    io::xml::write_file_atomically(settings_file, io::write_settings(stored));
    {
        std::ofstream log(dir / "run.log", std::ios::app);
        log << "resumed in place from population.xml\n" << run_log_head(r.command_line, std::chrono::system_clock::now());
        if (!log) throw std::runtime_error("cannot write " + (dir / "run.log").string());
    }
    RunOptions opt;
    opt.run_dir = dir;
    opt.quiet = r.quiet;
    opt.verbose = r.verbose;
    opt.worker_executable = self_exec_path();
    opt.continue_in_place = true;
    return run_experiment(std::move(prepared), opt);
}

} // namespace cic::app
