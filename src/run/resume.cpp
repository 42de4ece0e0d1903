// `cic resume RUN` (resume.hpp): a run continued in its own folder.
#include "cic/run/resume.hpp"

#include <chrono>
#include <fstream>
#include <iostream>
#include <optional>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/io/settings_table.hpp"
#include "cic/search/search.hpp"
#include "cic/io/xml.hpp"
#include "cic/run/provenance.hpp"
#include "cic/run/run.hpp"
#include "cic/run/run_history.hpp"
#include "cic/run/self_path.hpp"
#include "cic/run/settings_diff.hpp"

namespace cic::run {
namespace {

namespace fs = std::filesystem;

// A key's value as the settings table writes it ("Section.key").
std::string setting_value(const io::Settings& s, const std::string& key) {
    for (const auto& k : io::settings_table())
        if (k.section + "." + k.key == key) return k.get(s);
    throw std::logic_error("no settings key " + key);
}

// The budget line a resume says (run.log and the console): what it goes on
// with, against what the run had. Empty when the budget is unchanged.
std::string budget_line(const io::Settings& ran, const io::Settings& asked) {
    const search::SearchKind& kind = search::search_of(ran);
    if (const std::string a = setting_value(asked, kind.budget_key), r = setting_value(ran, kind.budget_key); a != r)
        return fmt::format("continuing with a budget of {} {} (was {})", a, kind.budget_unit, r);
    if (asked.control.minimum_fitness != ran.control.minimum_fitness)
        return fmt::format("continuing until fitness {} (was {})", asked.control.minimum_fitness,
                           ran.control.minimum_fitness);
    return {};
}

// Refuses a budget that lets the run do nothing more (exit 2, nothing
// written), as the same budget is refused at the start of a run: no further
// generation or batch, or a minimum fitness already reached. --generations and
// --until set Control.maximumIterations: only a search counted in it takes them.
void check_budget_goes_on(const ResumeRequest& r, const io::Settings& ran, io::Settings& asked,
                          const std::optional<fs::path>& checkpoint) {
    const std::string where = checkpoint ? checkpoint->string() : (r.run_dir / "settings.xml").string();
    const search::SearchKind& kind = search::search_of(ran);
    if (kind.budget_key != "Control.maximumIterations") {
        if (r.generations || r.until)
            throw InputError(fmt::format("a {} run's budget is its {} ({}): resume it with --set {}=E", kind.name,
                                         kind.budget_unit, kind.budget_key, kind.budget_key));
        return;   // the step check needs the checkpoint's state: after prepare_run
    }
    const int done = checkpoint ? search::load_checkpoint(kind, ran, checkpoint->string())->generations : 0;
    if (r.until) asked.control.maximum_iterations = *r.until;
    if (r.generations) asked.control.maximum_iterations = done + *r.generations;
    if (asked.control.maximum_iterations <= done)
        throw InputError(fmt::format("the run has evaluated {} generation{} (Control.maximumIterations {}); ask "
                                     "for more with --generations N or --until G (G > {})",
                                     done, done == 1 ? "" : "s", asked.control.maximum_iterations, done),
                         where);
}

} // namespace

int resume_run(const ResumeRequest& r) {
    std::error_code ec;
    const fs::path dir = fs::absolute(r.run_dir, ec);
    if (ec) throw InputError("cannot read the run folder: " + ec.message(), r.run_dir.string());
    const fs::path settings_file = dir / "settings.xml";
    if (!fs::exists(dir, ec) && !ec)
        throw InputError("not a run folder (settings.xml, and population.xml or no summary.txt yet): " + dir.string());
    // The folder's checkpoints, read and checked against each other (a symbolic
    // link loop or a folder that cannot be read is refused here, with its path).
    const std::optional<ResumePoint> point = resume_point(dir);
    // A run killed before its first checkpoint has settings.xml but no
    // checkpoint: it starts again in its folder, as the unbroken run did.
    if (!fs::is_regular_file(settings_file, ec) || (!point && fs::exists(dir / "summary.txt", ec)))
        throw InputError("not a run folder (settings.xml, and population.xml or no summary.txt yet): " + dir.string());
    const std::optional<fs::path> checkpoint = point ? std::optional<fs::path>(point->file) : std::nullopt;
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
        std::string budgets;
        for (const auto& k : search::budget_keys()) budgets += ", " + k;
        throw InputError(fmt::format("cannot continue {} with other settings than it ran ({}); resume changes only "
                                     "the budget (--generations, --until{}) and keys that change no result "
                                     "(workers): start a new run for other settings",
                                     dir.string(), text, budgets),
                         settings_file.string());
    }

    if (checkpoint) asked.control.population_load_from = checkpoint->string();
    PreparedRun prepared = prepare_run(asked);   // the checkpoint parsed and checked against the settings
    if (prepared.resume) {
        prepared.resume->check_goes_on(prepared.settings);
        check_agrees_with_folder(*prepared.resume, *point, dir);   // never rewrite the run's history
    }
    // Every check has passed: from here on the folder is written.
    remove_stale_temporaries(dir);
    if (prepared.resume) prepared.resume->search_note.clear();   // only the budget differs (checked above): said below
    const std::string budget = budget_line(ran, prepared.settings);
    io::Settings stored = prepared.settings;
    stored.control.population_load_from.clear();
    io::xml::write_file_atomically(settings_file, io::write_settings(stored));
    {
        std::ofstream log(dir / "run.log", std::ios::app);
        log << (checkpoint ? "resumed in place from " + checkpoint->lexically_relative(dir).string() + "\n"
                           : "resumed in place: killed before its first checkpoint, the run starts again\n")
            << run_log_head(r.command_line, std::chrono::system_clock::now());
        if (point && !point->note.empty()) log << point->note << '\n';
        if (!budget.empty()) log << budget << '\n';
        if (!log) throw std::runtime_error("cannot write " + (dir / "run.log").string());
    }
    if (!budget.empty() && !r.quiet) std::cerr << "cic: " << budget << '\n';
    if (point && !point->note.empty() && !r.quiet) std::cerr << "cic: " << point->note << '\n';
    RunOptions opt;
    opt.run_dir = dir;
    opt.quiet = r.quiet;
    opt.verbose = r.verbose;
    opt.worker_executable = self_exec_path();
    opt.continue_in_place = checkpoint.has_value();
    return run_experiment(std::move(prepared), opt);
}

} // namespace cic::run
