// `cic resume RUN` (resume.hpp): a run continued in its own folder.
#include "cic/run/resume.hpp"

#include <chrono>
#include <fstream>
#include <iostream>
#include <optional>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/experiments/gait/restarts.hpp"
#include "cic/experiments/gait/setup.hpp"
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

// The budget line a resume says (run.log and the console): what it goes on
// with, against what the run had. Empty when the budget is unchanged.
std::string budget_line(const io::Settings& ran, const io::Settings& asked) {
    if (ran.map_elites.enabled && asked.map_elites.evaluations != ran.map_elites.evaluations)
        return fmt::format("continuing with a budget of {} evaluations (was {})", asked.map_elites.evaluations,
                           ran.map_elites.evaluations);
    if (io::family_of(ran) == io::ExperimentFamily::Gait && !ran.map_elites.enabled &&
        asked.gait.evaluations != ran.gait.evaluations)
        return fmt::format("continuing with a budget of {} evaluations (was {})", asked.gait.evaluations,
                           ran.gait.evaluations);
    if (asked.control.maximum_iterations != ran.control.maximum_iterations)
        return fmt::format("continuing with a budget of {} generations (was {})", asked.control.maximum_iterations,
                           ran.control.maximum_iterations);
    if (asked.control.minimum_fitness != ran.control.minimum_fitness)
        return fmt::format("continuing until fitness {} (was {})", asked.control.minimum_fitness,
                           ran.control.minimum_fitness);
    return {};
}

// Refuses a budget that lets the run do nothing more (exit 2, nothing
// written), as the same budget is refused at the start of a run: no further
// batch, generation, or a minimum fitness already reached.
void check_budget_goes_on(const ResumeRequest& r, const io::Settings& ran, io::Settings& asked,
                          const std::optional<fs::path>& checkpoint) {
    const std::string where = checkpoint ? checkpoint->string() : (r.run_dir / "settings.xml").string();
    if (ran.map_elites.enabled || io::family_of(ran) == io::ExperimentFamily::Gait || ran.neural.switches()) {
        // Switch-HybrID's budget is Gait.evaluations too, over both phases.
        const char* key = ran.map_elites.enabled ? "MapElites.evaluations" : "Gait.evaluations";
        if (r.generations || r.until)
            throw InputError(fmt::format("a {} run's budget is its evaluations{}: resume it with --set {}=E",
                                         ran.map_elites.enabled ? "MAP-Elites"
                                         : ran.neural.switches() ? "Switch-HybrID" : "gait",
                                         ran.neural.switches() ? " over both phases" : "", key));
        return;   // the batch check needs the checkpoint's state: after prepare_run
    }
    const int done = checkpoint ? io::load_population(*checkpoint).population.generation + 1 : 0;
    if (r.until) asked.control.maximum_iterations = *r.until;
    if (r.generations) asked.control.maximum_iterations = done + *r.generations;
    if (asked.control.maximum_iterations <= done)
        throw InputError(fmt::format("the run has evaluated {} generation{} (Control.maximumIterations {}); ask "
                                     "for more with --generations N or --until G (G > {})",
                                     done, done == 1 ? "" : "s", asked.control.maximum_iterations, done),
                         where);
}

// The same for the evaluation budgets, once the checkpoint is read and its
// search replayed (the next batch's size is the optimiser's).
void check_batch_fits(const PreparedRun& p, const std::string& where) {
    const io::Settings& s = p.settings;
    auto refuse = [&](long spent, long budget, long batch, const char* key, const char* what) {
        throw InputError(fmt::format("the run has spent {} evaluations; a budget of {} adds no {} of {} (ask for "
                                     "--set {}={} or more)",
                                     spent, budget, what, batch, key, spent + batch),
                         where);
    };
    auto reached = [&](double best) {
        if (best >= s.control.minimum_fitness)
            throw InputError(fmt::format("the run reached Control.minimumFitness {} (best {}); to go on, raise it "
                                         "with --set Control.minimumFitness=F",
                                         s.control.minimum_fitness, best),
                             where);
    };
    if (p.archive_resume) {
        const io::ArchiveFile& a = *p.archive_resume;
        if (const auto* best = a.best()) reached(best->fitness);
        if (a.evaluations + s.map_elites.batch > s.map_elites.evaluations)
            refuse(a.evaluations, s.map_elites.evaluations, s.map_elites.batch, "MapElites.evaluations", "batch");
    } else if (p.gait_resume) {
        const io::GaitFile& g = *p.gait_resume;
        reached(g.champion.fitness);
        const gait::Search search = gait::resume_search(gait::Setup::from_settings(s), gait::restart_rule_of(s), g,
                                                        s.control.population_load_from);
        // A Switch-HybrID gait phase counts on from its HyperGP phase's evaluations.
        const long spent = g.evaluations + (g.handover ? g.handover->evaluations : 0);
        if (spent + search.next_batch_size() > s.gait.evaluations)
            refuse(spent, s.gait.evaluations, search.next_batch_size(), "Gait.evaluations", "generation");
    } else if (p.resume) {
        reached(p.resume->population.best().fitness);
        if (s.neural.switches() && p.resume->state.evaluations >= s.gait.evaluations)   // Switch-HybrID's HyperGP phase
            throw InputError(fmt::format("the run has spent {} of its {} evaluations; ask for more with "
                                         "--set Gait.evaluations=E (E > {})",
                                         p.resume->state.evaluations, s.gait.evaluations, p.resume->state.evaluations),
                             where);
    }
}

} // namespace

int resume_run(const ResumeRequest& r) {
    const fs::path dir = fs::absolute(r.run_dir);
    const fs::path settings_file = dir / "settings.xml", checkpoint_file = dir / "population.xml";
    // A run killed before its first checkpoint has settings.xml but no
    // population.xml: it starts again in its folder, as the unbroken run did.
    if (!fs::is_regular_file(settings_file) ||
        (!fs::is_regular_file(checkpoint_file) && fs::exists(dir / "summary.txt")))
        throw InputError("not a run folder (settings.xml, and population.xml or no summary.txt yet): " + dir.string());
    const std::optional<fs::path> checkpoint =
        fs::is_regular_file(checkpoint_file) ? std::optional<fs::path>(checkpoint_file) : std::nullopt;
    if (r.generations && r.until) throw InputError("--generations and --until: give one of them");
    const io::Settings ran = io::read_settings(settings_file);
    io::Settings asked = io::load_settings(settings_file, r.sets);
    check_budget_goes_on(r, ran, asked, checkpoint);

    std::vector<std::string> refused;
    for (const auto& d : settings_differences(ran, asked, "the resume"))
        if (!is_budget_difference(d)) refused.push_back(d);
    if (!refused.empty()) {
        std::string text;
        for (const auto& d : refused) text += (text.empty() ? "" : "; ") + d;
        throw InputError(fmt::format("cannot continue {} with other settings than it ran ({}); resume changes only "
                                     "the budget (--generations, --until, Control.minimumFitness, Gait.evaluations, "
                                     "MapElites.evaluations) and keys that change no result (workers): start a new run "
                                     "for other settings",
                                     dir.string(), text),
                         settings_file.string());
    }

    if (checkpoint) asked.control.population_load_from = checkpoint->string();
    PreparedRun prepared = prepare_run(asked);   // the checkpoint parsed and checked against the settings
    if (checkpoint) check_batch_fits(prepared, checkpoint->string());
    // Every check has passed: from here on the folder is written.
    prepared.search_note.clear();   // only the budget differs (checked above): said below
    const std::string budget = budget_line(ran, prepared.settings);
    io::Settings stored = prepared.settings;
    stored.control.population_load_from.clear();
    io::xml::write_file_atomically(settings_file, io::write_settings(stored));
    {
        std::ofstream log(dir / "run.log", std::ios::app);
        log << (checkpoint ? "resumed in place from population.xml\n"
                           : "resumed in place: killed before its first checkpoint, the run starts again\n")
            << run_log_head(r.command_line, std::chrono::system_clock::now());
        if (!budget.empty()) log << budget << '\n';
        if (!log) throw std::runtime_error("cannot write " + (dir / "run.log").string());
    }
    if (!budget.empty() && !r.quiet) std::cerr << "cic: " << budget << '\n';
    RunOptions opt;
    opt.run_dir = dir;
    opt.quiet = r.quiet;
    opt.verbose = r.verbose;
    opt.worker_executable = self_exec_path();
    opt.continue_in_place = checkpoint.has_value();
    return run_experiment(std::move(prepared), opt);
}

} // namespace cic::app
