// The MAP-Elites loop (MapElites.enabled) of both robot families: HyperGP
// genotypes or gait parameter vectors, varied by the emitter MapElites.emitter
// names (experiments/map_elites_emitters.hpp).
// One batch at a time, evaluated in the same worker processes or MPI ranks as
// every other run, with the same run folder, stop signals and progress line.
// A checkpoint is the archive itself (io/archive_xml.hpp); stats.csv gains the
// quality-diversity columns (io/stats_csv.hpp).
#include <algorithm>
#include <chrono>
#include <optional>

#include <fmt/format.h>

#include "cic/experiments/gait/setup.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/experiments/map_elites_grid.hpp"
#include "cic/experiments/map_elites_emitters.hpp"
#include "cic/core/error.hpp"
#include "cic/io/archive_xml.hpp"
#include "cic/io/emitter_names.hpp"
#include "cic/io/experiment_types.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/stats_csv.hpp"
#include "cic/report/replay.hpp"
#include "cic/sim/evaluate.hpp"
#include "run_support.hpp"

namespace cic::app::detail {
namespace {

using Clock = std::chrono::steady_clock;

// What differs between the families: how a solution is stored, evaluated and replayed.
template <class Solution>
struct Family {
    const sim::RobotSpec* robot = nullptr;   // the run's, already loaded
    io::CheckpointOrigin origin;             // written in every checkpoint
    typename gp::MapElites<Solution>::Batch evaluate;
    std::function<void(io::ArchiveElite&, const Solution&)> store;
    std::function<Solution(const io::ArchiveElite&)> load;
    std::function<sim::EvalResult(const Solution&)> replay;   // for the summary's eq. 7.1 terms
    std::function<std::string(const Solution&)> describe;
    std::function<std::string()> session_note = [] { return std::string(); };
};

template <class Solution>
io::ArchiveFile checkpoint_of(const gp::MapElites<Solution>& me, const Family<Solution>& family,
                              const io::Settings& s) {
    io::ArchiveFile a;
    a.origin = family.origin;
    a.experiment = s.experiment.type;
    a.settings_digest = io::settings_digest(s);
    a.seed = s.experiment.seed;
    a.batches = me.batches();
    a.evaluations = me.evaluations();
    a.failed = me.failed();
    a.rng = me.rng().state();
    a.descriptor = sim::to_string(s.map_elites.descriptor);
    a.grid = me.archive().spec();
    a.emitter_state = me.emitter_state();
    if (!a.emitter_state.empty()) a.emitter = io::resolved_emitter(s);
    for (const auto& [cell, e] : me.archive().elites()) {
        io::ArchiveElite out;
        out.cell = cell;
        out.fitness = e.fitness;
        out.descriptor = e.descriptor;
        family.store(out, e.solution);
        a.elites.push_back(std::move(out));
    }
    return a;
}

template <class Solution>
void restore(gp::MapElites<Solution>& me, const Family<Solution>& family, const io::ArchiveFile& a) {
    std::map<std::size_t, typename gp::GridArchive<Solution>::Elite> elites;
    for (const auto& e : a.elites) elites.emplace(e.cell, typename gp::GridArchive<Solution>::Elite{e.descriptor, e.fitness, family.load(e)});
    me.restore(elites, a.evaluations, a.failed, a.batches, a.rng, a.emitter_state);
}

// One stats.csv row per batch: the archive as the population.
template <class Solution>
gp::GenerationRecord record_of(const gp::GridArchive<Solution>& archive, int batch, long evaluations, int failed,
                               double wall, double seconds) {
    gp::GenerationRecord r;
    r.generation = batch;
    std::vector<double> f;
    for (const auto& [cell, e] : archive.elites()) f.push_back(e.fitness);
    fill_fitness_stats(r, std::move(f));
    r.evaluations = evaluations;
    r.failed = failed;
    r.wall_seconds = wall;
    r.generation_seconds = seconds;
    return r;
}

template <class Solution>
int loop(gp::MapElites<Solution>& me, const Family<Solution>& family, const PreparedRun& prepared,
         const RunOptions& opt, RunConsole& console) {
    namespace fs = std::filesystem;
    const io::Settings& s = prepared.settings;
    const long budget = s.map_elites.evaluations;
    const double offset = s.map_elites.qd_offset;
    const auto started = Clock::now();
    auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
    fs::create_directories(opt.run_dir / "populations");
    std::optional<io::StatsWriter> stats;
    if (prepared.archive_resume) {
        const io::ArchiveFile& a = *prepared.archive_resume;
        say_checkpoint_notes(prepared, console);
        restore(me, family, a);
        console.say(fmt::format("resuming from {} after batch {} ({} evaluations, {} elites)",
                                s.control.population_load_from, a.batches - 1, a.evaluations, a.elites.size()));
        stats.emplace(opt.continue_in_place
                          ? io::StatsWriter(opt.run_dir / "stats.csv", a.batches - 1, io::kArchiveStatsColumns)
                          : io::StatsWriter(opt.run_dir / "stats.csv", io::kArchiveStatsColumns));
    } else {
        stats.emplace(opt.run_dir / "stats.csv", io::kArchiveStatsColumns);
    }
    const int interval = std::max(1, s.experiment.checkpoint_interval);
    const int first_batch = me.batches();
    auto checkpoint = [&] {
        write_checkpoint(opt.run_dir, me.batches() - 1, io::to_xml(checkpoint_of(me, family, s)));
    };

    StopSignalGuard stop_signals;
    std::string reason;
    for (;;) {
        const auto* best = me.archive().best();
        if (best && best->fitness >= s.control.minimum_fitness) {
            reason = "minimum fitness reached";
            break;
        }
        if (stop_requested().load()) {
            reason = "interrupted";
            break;
        }
        // Whole batches only, so that a run extended with a larger budget
        // (cic resume, a sweep's extend) is the run that had it from the start.
        if (me.evaluations() + s.map_elites.batch > budget) {
            reason = "evaluation budget";
            break;
        }
        const auto t0 = Clock::now();
        const long failed_before = me.failed(), evaluations_before = me.evaluations();
        const int kept = me.step(family.evaluate, budget - me.evaluations());
        const double seconds = seconds_since(t0);
        const auto& archive = me.archive();
        const gp::GenerationRecord r = record_of(archive, me.batches() - 1, me.evaluations(),
                                                 static_cast<int>(me.failed() - failed_before), seconds_since(started),
                                                 seconds);
        const double qd = archive.qd_score(offset);
        stats->write(r, fmt::format("{:.17g},{:.17g},{},{}", qd, archive.coverage(), archive.filled(), kept));
        console.log(fmt::format("batch {} best {:.17g} qd_score {:.17g} coverage {:.6f} filled {} kept {} evaluations "
                                "{} {:.2f}s",
                                r.generation, r.best, qd, archive.coverage(), archive.filled(), kept, r.evaluations,
                                r.wall_seconds));
        const bool last = me.evaluations() + s.map_elites.batch > budget;
        if (me.batches() % interval == 0 || last) checkpoint();
        const int batch_size = s.map_elites.batch;
        const long left = budget - me.evaluations();
        const int max_batches = me.batches() + static_cast<int>(left / batch_size);
        ProgressLine p;
        p.generation = r.generation;
        p.max_generations = max_batches;
        p.evaluations_per_second =
            seconds > 0 ? static_cast<double>(me.evaluations() - evaluations_before) / seconds : 0.0;
        p.best = r.best;
        p.mean = r.mean;
        p.coverage = archive.coverage();
        const int done = me.batches() - first_batch;
        p.eta_seconds = done > 0 ? r.wall_seconds / done * (max_batches - me.batches()) : -1.0;
        console.progress(p);
    }
    if (const std::string note = family.session_note(); !note.empty()) console.log(note);

    const auto& archive = me.archive();
    std::string summary = fmt::format("stopped: {} after batch {}\n", reason, me.batches() - 1);
    if (const auto* best = archive.best()) {
        const auto cell = archive.cell_of(best->descriptor);
        summary += fmt::format("best: fitness {:.17g} in cell {} ({}) {}\n", best->fitness, archive.spec().cell_name(cell), cell,
                               family.describe(best->solution));
    } else {
        summary += "best: none (every evaluation failed)\n";
    }
    summary += fmt::format("evaluations: {} ({} failed)\narchive: {} of {} cells filled (coverage {:.4f}), QD-score "
                           "{:.17g} (offset {:g})\n",
                           me.evaluations(), me.failed(), archive.filled(), archive.cells(), archive.coverage(),
                           archive.qd_score(offset), offset);
    if (reason != "interrupted" && archive.best()) {
        const sim::EvalResult replayed = family.replay(archive.best()->solution);
        const auto [distance, elevation] = eq71_terms(*family.robot, replayed);
        summary += eq71_line(distance, elevation);
    }
    console.summary(summary);
    if (reason == "interrupted") {
        if (me.batches() > 0) checkpoint();
        return console.interrupted();
    }
    if (me.batches() > 0 && me.batches() % interval != 0 && me.evaluations() + s.map_elites.batch <= budget)
        checkpoint();   // stopped early (minimum fitness): the last batch's checkpoint
    finish_run(s, opt, console);
    return 0;
}

gp::VectorMapElitesConfig vector_config(const io::Settings& s, const gait::Setup& setup) {
    gp::VectorMapElitesConfig vc;
    vc.grid = experiments::map_elites_grid(s, setup.robot);
    vc.dimension = setup.dimension();
    vc.batch = s.map_elites.batch;
    vc.initial = s.map_elites.initial;
    vc.sigma = s.map_elites.sigma;
    return vc;
}

gp::MapElitesConfig config_of(const io::Settings& s, const sim::RobotSpec& robot) {
    return {experiments::map_elites_grid(s, robot), s.map_elites.batch, s.map_elites.initial};
}

int run_gait_family(PreparedRun prepared, const RunOptions& opt, RunConsole& console) {
    const io::Settings& s = prepared.settings;
    const gait::Setup setup = gait::Setup::from_settings(s);
    const experiments::Context ctx = make_context(s, opt, console);
    gait::Evaluator evaluator(ctx, setup);
    const sim::Descriptor descriptor = s.map_elites.descriptor;
    const gp::VectorMapElitesConfig vc = vector_config(s, setup);
    gp::MapElites<std::vector<double>> me(gp::MapElitesConfig{vc.grid, vc.batch, vc.initial},
                                          experiments::make_vector_emitter(s, vc), s.experiment.seed);
    Family<std::vector<double>> family;
    family.robot = &setup.robot;
    family.origin = io::origin_of(s, setup.robot);
    family.evaluate = [&](const std::vector<std::vector<double>>& xs) { return evaluator.described(xs, descriptor); };
    family.store = [](io::ArchiveElite& e, const std::vector<double>& x) { e.x = x; };
    family.load = [](const io::ArchiveElite& e) { return e.x; };   // its length checked by prepare_run
    family.replay = [&](const std::vector<double>& x) {
        const auto controller = setup.controller(x);
        return sim::evaluate(setup.robot, *controller, setup.sim);
    };
    family.describe = [&](const std::vector<double>& x) { return "gait: " + setup.describe(x); };
    console.say(fmt::format("cic {}: gait experiment by MAP-Elites ({} parameters, {} emitter, {} descriptor, {} "
                            "cells, batches of {}, budget {} evaluations), seed {}, output {}",
                            CIC_VERSION, setup.dimension(), io::resolved_emitter(s), sim::to_string(descriptor),
                            me.archive().cells(), vc.batch, s.map_elites.evaluations, s.experiment.seed,
                            opt.run_dir.string()));
    return loop(me, family, prepared, opt, console);
}

int run_hypergp_family(PreparedRun prepared, const RunOptions& opt, RunConsole& console) {
    const io::Settings& s = prepared.settings;
    const hypergp::Model model = hypergp::Model::from_settings(s);
    const experiments::Context ctx = make_context(s, opt, console);
    auto experiment = experiments::make_experiment(ctx);
    const tree::PrimitiveSet ps(s.gp.primitives);
    gp::MapElites<tree::Forest> me(config_of(s, model.robot), experiments::make_forest_emitter(s, ps),
                                   s.experiment.seed);
    Family<tree::Forest> family;
    family.robot = &model.robot;
    family.origin = io::origin_of(s, model.robot);
    family.evaluate = [&](const std::vector<tree::Forest>& forests) {
        std::vector<gp::IndividualPtr> todo;
        for (std::size_t i = 0; i < forests.size(); ++i) {
            auto ind = std::make_shared<gp::Individual>();
            ind->id = static_cast<std::uint64_t>(me.evaluations()) + i + 1;   // for warnings only
            ind->genotype = forests[i];
            todo.push_back(std::move(ind));
        }
        experiment->evaluator().evaluate(todo);
        std::vector<gp::Evaluation> out;
        for (const auto& ind : todo) out.push_back({ind->fitness, ind->descriptor, ind->failed});
        return out;
    };
    family.store = [](io::ArchiveElite& e, const tree::Forest& f) { e.genotype = f; };
    family.load = [](const io::ArchiveElite& e) { return e.genotype; };   // its shape checked by prepare_run
    family.replay = [&](const tree::Forest& f) { return hypergp::run(model, f).result; };
    family.describe = [&](const tree::Forest& f) {
        std::string trees;
        for (const auto& t : f) trees += (trees.empty() ? "" : " | ") + t.to_string();
        return fmt::format("size {} tree{}: {}", tree::total_size(f), f.size() > 1 ? "s" : "", trees);
    };
    family.session_note = [&] { return experiment->session_note(); };
    console.say(fmt::format("cic {}: {} experiment by MAP-Elites ({} emitter, {} descriptor, {} cells, batches of {}, "
                            "budget {} evaluations), seed {}, output {}",
                            CIC_VERSION, s.experiment.type, io::resolved_emitter(s), sim::to_string(s.map_elites.descriptor),
                            me.archive().cells(), s.map_elites.batch, s.map_elites.evaluations, s.experiment.seed,
                            opt.run_dir.string()));
    return loop(me, family, prepared, opt, console);
}

} // namespace

void check_archive_emitter(const io::Settings& s, const io::ArchiveFile& a, const std::string& file) {
    if (a.emitter_state.empty()) return;
    try {
        if (io::family_of(s) == io::ExperimentFamily::Gait) {
            const auto e = experiments::make_vector_emitter(s, vector_config(s, gait::Setup::from_settings(s)));
            if (!e.load) throw std::invalid_argument("this emitter keeps no state");
            e.load(a.emitter_state);
        } else {
            const tree::PrimitiveSet ps(s.gp.primitives);
            const auto e = experiments::make_forest_emitter(s, ps);
            if (!e.load) throw std::invalid_argument("this emitter keeps no state");
            e.load(a.emitter_state);
        }
    } catch (const std::invalid_argument& e) {
        throw InputError(std::string("<emitter>: ") + e.what(), file);
    }
}

int run_map_elites(PreparedRun prepared, const RunOptions& opt) {
    RunConsole console(opt);
    if (io::family_of(prepared.settings) == io::ExperimentFamily::Gait)
        return run_gait_family(std::move(prepared), opt, console);
    return run_hypergp_family(std::move(prepared), opt, console);
}

} // namespace cic::app::detail
