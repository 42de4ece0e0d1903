// The gait experiment's loop: a pagmo2 optimiser tunes an open-loop gait
// (experiments/gait/), one generation at a time, with the same run folder,
// statistics, checkpoints, progress and stop signals as the GP experiments.


#include <fmt/format.h>

#include <fstream>

#include "cic/run/progress.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/stats_csv.hpp"
#include "cic/report/replay.hpp"
#include "cic/sim/evaluate.hpp"
#include "cic/io/xml.hpp"
#include "cic/experiments/gait/restarts.hpp"
#include "cic/experiments/gait/setup.hpp"
#include "run_support.hpp"

namespace cic::app::detail {
namespace {

// After kStatsColumns: the best fitness of the run so far (`best` is each generation's).
constexpr const char* kGaitStatsColumns = "best_so_far";

// Where a gait phase's generations and evaluations start in the run: 0, or
// after Switch-HybrID's HyperGP phase.
struct Origin {
    int generation = 0;
    long evaluations = 0;
};

Origin origin_of(const std::optional<io::GaitHandover>& h) {
    return h ? Origin{h->generation + 1, h->evaluations} : Origin{};
}

// Statistics of the current candidates, in the columns GP runs write (the
// tree columns stay 0).
gp::GenerationRecord record_of(const gait::Search& search, const Origin& at, long failed, double wall,
                               double generation_seconds) {
    gp::GenerationRecord r;
    r.generation = at.generation + search.generation();
    std::vector<double> f;
    for (const auto& c : search.population()) f.push_back(c.fitness);
    fill_fitness_stats(r, std::move(f));
    r.evaluations = at.evaluations + search.evaluations();
    r.failed = static_cast<int>(failed);
    r.wall_seconds = wall;
    r.generation_seconds = generation_seconds;
    return r;
}

io::GaitFile checkpoint_of(const gait::Search& search, const io::Settings& s, const io::CheckpointOrigin& origin,
                           const std::optional<io::GaitHandover>& handover) {
    io::GaitFile g;
    g.origin = origin;
    g.settings_digest = io::settings_digest(s);
    g.optimizer = gait::to_string(search.optimizer());
    g.seed = search.seed();
    g.generation = search.generation();
    g.evaluations = search.evaluations();
    g.dimension = search.dimension();
    for (const auto& c : search.population()) g.population.push_back({c.x, c.fitness});
    g.champion = {search.champion().x, search.champion().fitness};
    g.history = search.history();
    if (search.restart_rule().mode != gait::Restarts::None) g.restarts = gait::restart_record_of(search);
    g.handover = handover;
    return g;
}

} // namespace

int run_gait(PreparedRun prepared, const RunOptions& opt) {
    RunConsole console(opt);
    StopSignalGuard stop_signals;
    return run_gait_phase(prepared, opt, console, std::nullopt, "");
}

int run_gait_phase(PreparedRun& prepared, const RunOptions& opt, RunConsole& console,
                   const std::optional<io::GaitHandover>& handover, const std::string& summary_head) {
    namespace fs = std::filesystem;
    using Clock = std::chrono::steady_clock;
    const io::Settings& s = prepared.settings;
    const Origin at = origin_of(handover);
    auto say = [&](const std::string& line) { console.say(line); };
    const int workers = resolved_workers(s);
    const gait::Setup setup = gait::Setup::from_settings(s);
    const gait::RestartRule restart_rule = gait::restart_rule_of(s);
    const bool ipop = restart_rule.mode == gait::Restarts::Ipop;
    const io::CheckpointOrigin origin = io::origin_of(s, setup.robot);
    gait::Search search = prepared.gait_resume
        ? gait::resume_search(setup, restart_rule, *prepared.gait_resume, s.control.population_load_from)
        : gait::make_search(setup, restart_rule, s.experiment.seed);
    if (handover && !prepared.gait_resume) search.set_start(handover->x);   // Switch-HybrID: from HyperGP's best
    say(fmt::format("cic {}: gait experiment ({} over {} parameters, {} candidates per generation, budget {} "
                    "evaluations), seed {}, {} worker{}, output {}",
                    CIC_VERSION, gait::to_string(setup.optimizer), setup.dimension(), setup.population,
                    s.gait.evaluations, s.experiment.seed, workers, workers == 1 ? "" : "s", opt.run_dir.string()));
    if (!ipop && s.gait.evaluations % setup.population != 0)   // whole generations only: said, not done silently
        say(fmt::format("note: Gait.evaluations {} is not a whole number of generations of {} candidates; the run "
                        "stops after {} generations, at {} evaluations",
                        s.gait.evaluations, setup.population, s.gait.evaluations / setup.population,
                        s.gait.evaluations / setup.population * setup.population));
    if (ipop)
        say(fmt::format("ipop restarts: a start stagnates when its best rises by <= {:g} over {} generations{}; "
                        "each restart doubles the population",
                        restart_rule.tolerance,
                        restart_rule.patience > 0 ? std::to_string(restart_rule.patience)
                                                  : "10 + ceil(30 n / lambda)",
                        restart_rule.tol_x > 0 ? fmt::format(", or collapses below a spread of {:g}", restart_rule.tol_x)
                                               : ""));
    const experiments::Context ctx = make_context(s, opt, console);
    gait::Evaluator evaluator(ctx, setup);
    long failed_before = 0;
    const gait::BatchEvaluator batch = [&](const std::vector<std::vector<double>>& xs) { return evaluator(xs); };

    const auto started = Clock::now();
    auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
    std::optional<io::StatsWriter> stats;
    fs::create_directories(opt.run_dir / "populations");
    // A run resumed in place from a file written before the column keeps its header;
    // a Switch-HybrID run's stats.csv has its HyperGP phase's columns.
    bool with_best_so_far = !handover;
    if (with_best_so_far && prepared.gait_resume && opt.continue_in_place) {
        std::ifstream in(opt.run_dir / "stats.csv");
        std::string header;
        std::getline(in, header);
        with_best_so_far = header.empty() || header.find(",best_so_far") != std::string::npos;
    }
    int restarts_said = search.restarts();
    int last_stalled = 0;          // why the restart a step begins was decided
    bool last_collapsed = false;
    auto after_generation = [&](double generation_seconds) {
        if (search.restarts() > restarts_said) {
            restarts_said = search.restarts();
            say(fmt::format("restart {}: population {} from generation {}, after {} generations without improvement "
                            "of more than {:g}{}",
                            search.restarts(), search.population_size(), at.generation + search.generation(),
                            last_stalled, restart_rule.tolerance, last_collapsed ? " (the candidates had collapsed)" : ""));
        }
        const gp::GenerationRecord r = record_of(search, at, evaluator.failed() - failed_before,
                                                 seconds_since(started), generation_seconds);
        failed_before = evaluator.failed();
        // `best` is this generation's; best_so_far the run's (the console's and the replay's).
        stats->write(r, with_best_so_far ? fmt::format("{:.17g}", search.champion().fitness) : std::string());
        console.log(fmt::format("gen {} best {:.17g} mean {:.17g} median {:.17g} champion {:.17g} evaluations {} {:.2f}s",
                                r.generation, r.best, r.mean, r.median, search.champion().fitness, r.evaluations,
                                r.wall_seconds));
        const int interval = std::max(1, s.experiment.checkpoint_interval);
        if ((r.generation + 1) % interval == 0 || s.gait.evaluations - r.evaluations < search.next_batch_size())
            write_checkpoint(opt.run_dir, r.generation, io::to_xml(checkpoint_of(search, s, origin, handover)));
        const long per_generation = search.population_size();
        // The generations the budget allows at the next batch's size (without
        // restarts: floor(budget / lambda)).
        const int max_generations =
            r.generation + 1 +
            static_cast<int>(std::max(0L, s.gait.evaluations - r.evaluations) / search.next_batch_size());
        ProgressLine p;
        p.generation = r.generation;
        p.max_generations = max_generations;
        p.evaluations_per_second = generation_seconds > 0 ? per_generation / generation_seconds : 0.0;
        p.best = search.champion().fitness;
        p.mean = r.mean;
        p.eta_seconds = generation_seconds * std::max(0, max_generations - (r.generation + 1));
        console.progress(p);
    };

    if (prepared.gait_resume) {
        io::GaitFile& g = *prepared.gait_resume;
        say_checkpoint_notes(prepared, console);
        say(fmt::format("resuming from {} at generation {} ({} evaluations)", s.control.population_load_from,
                        g.generation, g.evaluations));
        const std::string extra = with_best_so_far ? kGaitStatsColumns : "";
        stats.emplace(opt.continue_in_place
                          ? io::StatsWriter(opt.run_dir / "stats.csv", at.generation + g.generation, extra)
                          : io::StatsWriter(opt.run_dir / "stats.csv", extra));
    } else if (handover) {   // Switch-HybrID: stats.csv goes on from the HyperGP phase's rows
        stats.emplace(opt.run_dir / "stats.csv", handover->generation);
        if (detail::stop_requested().load()) {   // stopped as HyperGP handed over: its checkpoint resumes
            console.summary(summary_head + "stopped: interrupted before the gait phase began\n");
            return console.interrupted();
        }
        const auto t0 = Clock::now();
        search.initialise(batch);
        after_generation(seconds_since(t0));
    } else {
        stats.emplace(opt.run_dir / "stats.csv", kGaitStatsColumns);
        const auto t0 = Clock::now();
        search.initialise(batch);
        after_generation(seconds_since(t0));
    }

    std::string reason;
    const int first_generation = search.generation();
    for (;;) {
        if (search.champion().fitness >= s.control.minimum_fitness) {
            reason = "minimum fitness reached";
            break;
        }
        if (detail::stop_requested().load()) {
            reason = "interrupted";
            break;
        }
        if (at.evaluations + search.evaluations() + search.next_batch_size() > s.gait.evaluations) {
            reason = "evaluation budget";
            break;
        }
        const auto t0 = Clock::now();
        last_stalled = search.stalled_generations();
        last_collapsed = search.collapsed();
        search.step(batch);
        after_generation(seconds_since(t0));
    }
    // A resume from a run's last checkpoint ends at once: the run's final state
    // goes into this folder too (as the GP loop saves a resumed last generation again).
    if (prepared.gait_resume && search.generation() == first_generation && reason != "interrupted")
        write_checkpoint(opt.run_dir, at.generation + search.generation(),
                         io::to_xml(checkpoint_of(search, s, origin, handover)));

    const gait::Candidate& best = search.champion();
    const std::string summary =
        summary_head +
        fmt::format("stopped: {} at generation {}\nbest: fitness {:.17g} ({}; robot {})\nevaluations: {}\nbest gait: {}\n",
                    reason, at.generation + search.generation(), best.fitness, gait::to_string(setup.optimizer),
                    setup.robot.name, at.evaluations + search.evaluations(), setup.describe(best.x));
    std::string walk;
    if (reason != "interrupted") {   // the champion again: what its score is made of
        const auto controller = setup.controller(best.x);
        const sim::EvalResult r = sim::evaluate(setup.robot, *controller, setup.sim);
        const auto [distance, elevation] = eq71_terms(setup.robot, r);
        walk = eq71_line(distance, elevation);
    }
    console.summary((ipop ? summary + fmt::format("restarts: {} (population {})\n", search.restarts(),
                                                  search.population_size())
                          : summary) +
                    walk);
    if (reason == "interrupted") {
        // The checkpoint of the last finished generation is on disk unless the interval skipped it.
        write_checkpoint(opt.run_dir, at.generation + search.generation(),
                         io::to_xml(checkpoint_of(search, s, origin, handover)));
        return console.interrupted();
    }
    finish_run(s, opt, console);
    return 0;
}

} // namespace cic::app::detail
