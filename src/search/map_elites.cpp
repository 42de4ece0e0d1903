// MAP-Elites (MapElites.enabled) as a search, over either genotype form:
// HyperGP trees or gait vectors, varied by the emitter MapElites.emitter
// names (experiments/map_elites_emitters.hpp). One batch per step, within the
// budget MapElites.evaluations. Its checkpoint is the archive itself
// (io/archive_xml.hpp); stats.csv gains the quality-diversity columns.
#include <map>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/experiments/gait/setup.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/experiments/map_elites_emitters.hpp"
#include "cic/experiments/map_elites_grid.hpp"
#include "cic/gp/map_elites.hpp"
#include "cic/io/archive_xml.hpp"
#include "cic/io/checkpoint_origin.hpp"
#include "cic/io/emitter_names.hpp"
#include "cic/io/stats_csv.hpp"
#include "cic/report/replay.hpp"
#include "cic/search/support.hpp"
#include "cic/sim/evaluate.hpp"

namespace cic::search {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

gp::VectorMapElitesConfig vector_config(const io::Settings& s, const gait::Setup& setup) {
    gp::VectorMapElitesConfig vc;
    vc.grid = experiments::map_elites_grid(s, setup.robot);
    vc.dimension = setup.dimension();
    vc.batch = s.map_elites.batch;
    vc.initial = s.map_elites.initial;
    vc.sigma = s.map_elites.sigma;
    return vc;
}

// Throws cic::InputError naming `file` when the archive's emitter state is one
// the settings' emitter cannot take back (before a resume writes anything).
void check_archive_emitter(const io::Settings& s, const io::ArchiveFile& a, const std::string& file) {
    if (a.emitter_state.empty()) return;
    try {
        if (io::genotype_form(s) == io::GenotypeForm::Vector) {
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

class ArchiveCheckpoint : public Checkpoint {
public:
    io::ArchiveFile archive;
    void check_goes_on(const io::Settings& s) const override {
        if (const auto* best = archive.best()) refuse_if_reached(best->fitness, s, file);
        if (archive.evaluations + s.map_elites.batch > s.map_elites.evaluations)
            throw InputError(fmt::format("the run has spent {} evaluations; a budget of {} adds no batch of {} (ask "
                                         "for --set MapElites.evaluations={} or more)",
                                         archive.evaluations, s.map_elites.evaluations, s.map_elites.batch,
                                         archive.evaluations + s.map_elites.batch),
                             file);
    }
};

std::unique_ptr<Checkpoint> load_archive_checkpoint(const io::Settings& s, const std::string& file) {
    auto c = std::make_unique<ArchiveCheckpoint>();
    c->file = file;
    c->archive = io::load_archive(file);
    c->origin_note = io::check_origin(c->archive.origin, s, file);
    c->settings_digest = c->archive.settings_digest;
    c->generations = c->archive.batches;
    c->number = c->archive.batches - 1;
    c->evaluations = c->archive.evaluations;
    const bool vector = io::genotype_form(s) == io::GenotypeForm::Vector;
    std::optional<gait::Setup> setup;
    if (vector) setup = gait::Setup::from_settings(s);
    const sim::RobotSpec robot = setup ? setup->robot : hypergp::Model::from_settings(s).robot;
    io::check_compatible(c->archive, s, experiments::map_elites_grid(s, robot), setup ? setup->dimension() : 0, file);
    check_archive_emitter(s, c->archive, file);
    return c;
}

// What differs between the genotype forms: how a solution is stored, evaluated and replayed.
template <class Solution>
struct Form {
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
class MapElitesSearch : public Search {
public:
    MapElitesSearch(const Services& services, std::unique_ptr<ArchiveCheckpoint> resume,
                    std::unique_ptr<gp::MapElites<Solution>> me, Form<Solution> form)
        : services_(services), resume_(std::move(resume)), form_(std::move(form)), me_(std::move(me)) {}

    StatsLayout stats_layout() const override {
        StatsLayout l{io::kArchiveStatsColumns, std::nullopt};
        if (resume_ && services_.continue_in_place) l.continue_after = resume_->archive.batches - 1;
        return l;
    }

    std::optional<Row> start() override {
        if (resume_) {
            const io::ArchiveFile& a = resume_->archive;
            say_checkpoint_notes(*resume_, services_);
            std::map<std::size_t, typename gp::GridArchive<Solution>::Elite> elites;
            for (const auto& e : a.elites)
                elites.emplace(e.cell, typename gp::GridArchive<Solution>::Elite{e.descriptor, e.fitness, form_.load(e)});
            me_->restore(elites, a.evaluations, a.failed, a.batches, a.rng, a.emitter_state);
            services_.say(fmt::format("resuming from {} after batch {} ({} evaluations, {} elites)", resume_->file,
                                      a.batches - 1, a.evaluations, a.elites.size()));
        }
        first_batch_ = me_->batches();
        return std::nullopt;   // the first batch is a step like every other
    }

    Stop stop(bool signal) override {
        const io::Settings& s = services_.settings;
        const auto* best = me_->archive().best();
        if (best && best->fitness >= s.control.minimum_fitness) return {"minimum fitness reached", false};
        if (signal) return {"interrupted", true};
        // Whole batches only, so that a run extended with a larger budget
        // (cic resume, a sweep's extend) is the run that had it from the start.
        if (me_->evaluations() + s.map_elites.batch > s.map_elites.evaluations) return {"evaluation budget", false};
        return {};
    }

    bool checkpoint_due(const Stop& stop) override {
        const io::Settings& s = services_.settings;
        const bool stepped = std::exchange(stepped_, false);
        const int interval = std::max(1, s.experiment.checkpoint_interval);
        const bool last = me_->evaluations() + s.map_elites.batch > s.map_elites.evaluations;
        if (stepped && (me_->batches() % interval == 0 || last)) return true;
        if (me_->batches() == 0) return false;
        if (stop.interrupted) return true;
        // A resume from a run's last checkpoint ends at once: the run's final state
        // goes into this folder too, as the other searches do.
        if (stop.done() && resume_ && me_->batches() == first_batch_) return true;
        // Stopped early (minimum fitness): the last batch's checkpoint.
        return stop.done() && me_->batches() % interval != 0 && !last;
    }

    CheckpointText checkpoint() const override {
        const io::Settings& s = services_.settings;
        io::ArchiveFile a;
        a.origin = form_.origin;
        a.experiment = s.experiment.type;
        a.settings_digest = io::settings_digest(s);
        a.seed = s.experiment.seed;
        a.batches = me_->batches();
        a.evaluations = me_->evaluations();
        a.failed = me_->failed();
        a.rng = me_->rng().state();
        a.descriptor = sim::to_string(s.map_elites.descriptor);
        a.grid = me_->archive().spec();
        a.emitter_state = me_->emitter_state();
        if (!a.emitter_state.empty()) a.emitter = io::resolved_emitter(s);
        for (const auto& [cell, e] : me_->archive().elites()) {
            io::ArchiveElite out;
            out.cell = cell;
            out.fitness = e.fitness;
            out.descriptor = e.descriptor;
            form_.store(out, e.solution);
            a.elites.push_back(std::move(out));
        }
        return {me_->batches() - 1, io::to_xml(a)};
    }

    Row step() override {
        const io::Settings& s = services_.settings;
        const long budget = s.map_elites.evaluations;
        const auto t0 = Clock::now();
        const long failed_before = me_->failed(), evaluations_before = me_->evaluations();
        const int kept = me_->step(form_.evaluate, budget - me_->evaluations());
        const double seconds = seconds_since(t0);
        const auto& archive = me_->archive();
        Row row;
        gp::GenerationRecord& r = row.record;
        r.generation = me_->batches() - 1;
        std::vector<double> f;
        for (const auto& [cell, e] : archive.elites()) f.push_back(e.fitness);
        fill_fitness_stats(r, std::move(f));
        r.evaluations = me_->evaluations();
        r.failed = static_cast<int>(me_->failed() - failed_before);
        r.wall_seconds = seconds_since(started_);
        r.generation_seconds = seconds;
        const double qd = archive.qd_score(s.map_elites.qd_offset);
        row.extra = fmt::format("{:.17g},{:.17g},{},{}", qd, archive.coverage(), archive.filled(), kept);
        row.log = fmt::format("batch {} best {:.17g} qd_score {:.17g} coverage {:.6f} filled {} kept {} evaluations "
                              "{} {:.2f}s",
                              r.generation, r.best, qd, archive.coverage(), archive.filled(), kept, r.evaluations,
                              r.wall_seconds);
        const int max_batches = me_->batches() + static_cast<int>((budget - me_->evaluations()) / s.map_elites.batch);
        ProgressLine& p = row.progress;
        p.generation = r.generation;
        p.max_generations = max_batches;
        p.evaluations_per_second =
            seconds > 0 ? static_cast<double>(me_->evaluations() - evaluations_before) / seconds : 0.0;
        p.best = r.best;
        p.mean = r.mean;
        p.coverage = archive.coverage();
        const int done = me_->batches() - first_batch_;
        p.eta_seconds = done > 0 ? r.wall_seconds / done * (max_batches - me_->batches()) : -1.0;
        stepped_ = true;
        return row;
    }

    std::string summary(const Stop& stop) override {
        const io::Settings& s = services_.settings;
        const double offset = s.map_elites.qd_offset;
        if (const std::string note = form_.session_note(); !note.empty()) services_.log(note);
        const auto& archive = me_->archive();
        std::string text = fmt::format("stopped: {} after batch {}\n", stop.reason, me_->batches() - 1);
        if (const auto* best = archive.best()) {
            const auto cell = archive.cell_of(best->descriptor);
            text += fmt::format("best: fitness {:.17g} in cell {} ({}) {}\n", best->fitness,
                                archive.spec().cell_name(cell), cell, form_.describe(best->solution));
        } else {
            text += "best: none (every evaluation failed)\n";
        }
        text += fmt::format("evaluations: {} ({} failed)\narchive: {} of {} cells filled (coverage {:.4f}), QD-score "
                            "{:.17g} (offset {:g})\n",
                            me_->evaluations(), me_->failed(), archive.filled(), archive.cells(), archive.coverage(),
                            archive.qd_score(offset), offset);
        if (!stop.interrupted && archive.best()) {
            const sim::EvalResult replayed = form_.replay(archive.best()->solution);
            const auto [distance, elevation] = report::eq71_terms(*form_.robot, replayed);
            text += eq71_line(distance, elevation);
        }
        return text;
    }

private:
    Services services_;
    std::unique_ptr<ArchiveCheckpoint> resume_;
    Form<Solution> form_;   // before me_: its lambdas hold what the emitter refers to
    std::unique_ptr<gp::MapElites<Solution>> me_;
    bool stepped_ = false;
    int first_batch_ = 0;
    Clock::time_point started_ = Clock::now();
};

// Gait vectors: the setup and evaluator live as long as the search (its lambdas hold them).
std::unique_ptr<Search> make_vector_search(const Services& services, std::unique_ptr<ArchiveCheckpoint> resume) {
    const io::Settings& s = services.settings;
    struct Parts {
        Parts(const Services& services)
            : setup(gait::Setup::from_settings(services.settings)), evaluator(services.context, setup) {}
        gait::Setup setup;
        gait::Evaluator evaluator;   // holds a reference to setup
    };
    auto parts = std::make_shared<Parts>(services);
    const gp::VectorMapElitesConfig vc = vector_config(s, parts->setup);
    auto me = std::make_unique<gp::MapElites<std::vector<double>>>(
        gp::MapElitesConfig{vc.grid, vc.batch, vc.initial}, experiments::make_vector_emitter(s, vc), s.experiment.seed);
    const sim::Descriptor descriptor = s.map_elites.descriptor;
    Form<std::vector<double>> f;
    f.robot = &parts->setup.robot;
    f.origin = io::origin_of(s, parts->setup.robot);
    f.evaluate = [parts, descriptor](const std::vector<std::vector<double>>& xs) {
        return parts->evaluator.described(xs, descriptor);
    };
    f.store = [](io::ArchiveElite& e, const std::vector<double>& x) { e.x = x; };
    f.load = [](const io::ArchiveElite& e) { return e.x; };   // its length checked by the reader
    f.replay = [parts](const std::vector<double>& x) {
        const auto controller = parts->setup.controller(x);
        return sim::evaluate(parts->setup.robot, *controller, parts->setup.sim);
    };
    f.describe = [parts](const std::vector<double>& x) { return "gait: " + parts->setup.describe(x); };
    services.say(fmt::format("cic {}: gait experiment by MAP-Elites ({} parameters, {} emitter, {} descriptor, {} "
                             "cells, batches of {}, budget {} evaluations), seed {}, output {}",
                             CIC_VERSION, parts->setup.dimension(), io::resolved_emitter(s),
                             sim::to_string(descriptor), me->archive().cells(), vc.batch, s.map_elites.evaluations,
                             s.experiment.seed, services.run_dir.string()));
    return std::make_unique<MapElitesSearch<std::vector<double>>>(services, std::move(resume), std::move(me),
                                                                  std::move(f));
}

// HyperGP trees: evaluated by the experiment type's evaluator, replayed by its model.
std::unique_ptr<Search> make_forest_search(const Services& services, std::unique_ptr<ArchiveCheckpoint> resume) {
    const io::Settings& s = services.settings;
    struct Parts {
        Parts(const Services& services)
            : model(hypergp::Model::from_settings(services.settings)), primitives(services.settings.gp.primitives),
              experiment(experiments::make_experiment(services.context)) {}
        hypergp::Model model;
        tree::PrimitiveSet primitives;   // the emitter holds a reference to it
        std::unique_ptr<experiments::Experiment> experiment;
        const gp::MapElites<tree::Forest>* me = nullptr;
    };
    auto parts = std::make_shared<Parts>(services);
    auto me = std::make_unique<gp::MapElites<tree::Forest>>(
        gp::MapElitesConfig{experiments::map_elites_grid(s, parts->model.robot), s.map_elites.batch,
                            s.map_elites.initial},
        experiments::make_forest_emitter(s, parts->primitives), s.experiment.seed);
    parts->me = me.get();
    Form<tree::Forest> f;
    f.robot = &parts->model.robot;
    f.origin = io::origin_of(s, parts->model.robot);
    f.evaluate = [parts](const std::vector<tree::Forest>& forests) {
        std::vector<gp::IndividualPtr> todo;
        for (std::size_t i = 0; i < forests.size(); ++i) {
            auto ind = std::make_shared<gp::Individual>();
            ind->id = static_cast<std::uint64_t>(parts->me->evaluations()) + i + 1;   // for warnings only
            ind->genotype = forests[i];
            todo.push_back(std::move(ind));
        }
        parts->experiment->evaluator().evaluate(todo);
        std::vector<gp::Evaluation> out;
        for (const auto& ind : todo) out.push_back({ind->fitness, ind->descriptor, ind->failed});
        return out;
    };
    f.store = [](io::ArchiveElite& e, const tree::Forest& forest) { e.genotype = forest; };
    f.load = [](const io::ArchiveElite& e) { return e.genotype; };   // its shape checked by the reader
    f.replay = [parts](const tree::Forest& forest) { return hypergp::run(parts->model, forest).result; };
    f.describe = [](const tree::Forest& forest) {
        std::string trees;
        for (const auto& t : forest) trees += (trees.empty() ? "" : " | ") + t.to_string();
        return fmt::format("size {} tree{}: {}", tree::total_size(forest), forest.size() > 1 ? "s" : "", trees);
    };
    f.session_note = [parts] { return parts->experiment->session_note(); };
    services.say(fmt::format("cic {}: {} experiment by MAP-Elites ({} emitter, {} descriptor, {} cells, batches of "
                             "{}, budget {} evaluations), seed {}, output {}",
                             CIC_VERSION, s.experiment.type, io::resolved_emitter(s),
                             sim::to_string(s.map_elites.descriptor), me->archive().cells(), s.map_elites.batch,
                             s.map_elites.evaluations, s.experiment.seed, services.run_dir.string()));
    return std::make_unique<MapElitesSearch<tree::Forest>>(services, std::move(resume), std::move(me), std::move(f));
}

const Registrar registrar{SearchKind{
    .name = "map-elites",
    .doc = {},   // a built-in: its name and doc are the settings' (io/search_names.cpp)
    .forms = {io::GenotypeForm::Trees, io::GenotypeForm::Vector},
    .keys = {},
    .budget_key = "MapElites.evaluations",
    .budget_unit = "evaluations",
    .claims = [](const io::Settings& s) { return s.map_elites.enabled; },
    .claimed_by = "MapElites.enabled = 1",
    .fallback = false,
    .load = load_archive_checkpoint,
    .checkpoint_schema = {},   // its io reader checks the shipped settings/cic-archive.xsd
    .checkpoint_root = {},
    .best = {},
    .make = [](const Services& services, std::unique_ptr<Checkpoint> resume) -> std::unique_ptr<Search> {
        std::unique_ptr<ArchiveCheckpoint> archive(static_cast<ArchiveCheckpoint*>(resume.release()));
        if (io::genotype_form(services.settings) == io::GenotypeForm::Vector)
            return make_vector_search(services, std::move(archive));
        return make_forest_search(services, std::move(archive));
    },
}};

} // namespace
} // namespace cic::search
