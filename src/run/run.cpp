// The main job: settings -> search -> the one run loop, with statistics,
// checkpoints, progress and Ctrl-C handling around it. The loop knows no
// family and no search: each search is a block (search/search.hpp).
#include "cic/run/run.hpp"

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/experiments/experiment.hpp"
#include "cic/io/stats_csv.hpp"
#include "cic/report/verify.hpp"
#include "cic/search/support.hpp"
#include "run_support.hpp"

namespace cic::run {

using detail::finish_run;
using detail::make_context;
using detail::RunConsole;
using detail::StopSignalGuard;
using detail::write_checkpoint;

PreparedRun prepare_run(io::Settings s) {
    experiments::check_inputs(s);
    PreparedRun p;
    try {
        p.search = &search::search_of(s);
    } catch (const InputError& e) {
        throw InputError("<Experiment> search: " + e.message(), e.file(), e.line());
    }
    if (const std::string from = s.control.population_load_from; !from.empty()) {   // absolute: resolved when read
        try {
            p.resume = search::load_checkpoint(*p.search, s, from);
            // Replay before you believe: the champion's fitness must be what its genotype gives.
            report::refuse_unless_champion_replays(s, from);
            if (const std::string problem = report::handover_problem(s, from); !problem.empty())
                throw InputError(problem + "; the gait phase must start from the HyperGP phase's best");
        } catch (const InputError& e) {
            throw InputError("<Control> populationXmlLoadFrom: " + e.message(), e.file(), e.line());
        }
        p.resume->search_note = search::search_note(p.resume->settings_digest, s, from);
    }
    p.settings = std::move(s);
    return p;
}

int run_experiment(PreparedRun prepared, const RunOptions& opt) {
    const io::Settings& s = prepared.settings;
    RunConsole console(opt);
    StopSignalGuard stop_signals;   // one for the whole run: a signal between a search's phases is not lost
    const experiments::Context context = make_context(s, opt, console);
    const search::Services services{s, context, opt.run_dir, opt.continue_in_place,
                                    [&console](const std::string& line) { console.say(line); },
                                    [&console](const std::string& line) { console.log(line); }};
    const std::unique_ptr<search::Search> search = prepared.search->make(services, std::move(prepared.resume));

    std::filesystem::create_directories(opt.run_dir / "populations");
    const search::StatsLayout layout = search->stats_layout();
    io::StatsWriter stats = layout.continue_after
        ? io::StatsWriter(opt.run_dir / "stats.csv", *layout.continue_after, layout.extra_columns)
        : io::StatsWriter(opt.run_dir / "stats.csv", layout.extra_columns);
    auto emit = [&](const search::Row& row) {
        stats.write(row.record, row.extra);
        console.log(row.log);
        console.progress(row.progress);
    };

    if (const auto first = search->start()) emit(*first);
    search::Stop stop;
    for (;;) {
        stop = search->stop(detail::stop_requested().load());
        if (search->checkpoint_due(stop)) {
            const search::CheckpointText c = search->checkpoint();
            write_checkpoint(opt.run_dir, c.number, c.text);
        }
        if (stop.done()) break;
        emit(search->step());
    }
    console.summary(search->summary(stop), stop.interrupted ? RunEnd::Interrupted : RunEnd::Done);
    if (stop.interrupted) return console.interrupted();
    finish_run(s, opt, console);
    return 0;
}

} // namespace cic::run
