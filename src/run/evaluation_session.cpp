// Scoring genotypes from outside a run (cic/run/evaluation_session.hpp): the
// settings' own experiment wiring, job texts and worker processes.
#include "cic/run/evaluation_session.hpp"
#include "cic/report/run_genotype.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>

#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/core/job_runner.hpp"
#include "cic/experiments/experiment.hpp"
#include "cic/experiments/gait/setup.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/experiments/registry.hpp"
#include "cic/gp/individual.hpp"
#include "cic/io/archive_xml.hpp"
#include "cic/io/experiment_types.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/io/xml.hpp"
#include "cic/run/settings_lookup.hpp"
#include "cic/sim/evaluate.hpp"
#include "cic/sim/job_text.hpp"
#include "cic/tree/primitives.hpp"
#include "cic/tree/tree.hpp"

namespace cic::run {
namespace fs = std::filesystem;

namespace {

constexpr const char* kFolderPrefix = "cic-eval-";

// A process's start time (field 22 of /proc/PID/stat, clock ticks since boot):
// with the pid it names one process, even once the pid has been reused. Empty
// when the process is gone.
std::string process_start(long pid) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
    std::string stat;
    if (!std::getline(in, stat)) return {};
    const auto close = stat.rfind(')');   // the command name may hold spaces and parentheses
    if (close == std::string::npos) return {};
    std::istringstream fields(stat.substr(close + 2));
    std::string field;
    for (int i = 3; i <= 22 && fields >> field; ++i)
        if (i == 22) return field;
    return {};
}

// Folders of sessions that were killed (SIGKILL runs no destructor): each
// folder names its owner (pid and start time) in `owner`; one of this user's
// whose owner is gone is removed. A folder without `owner` (being made, or by
// an older cic) is left alone.
void remove_orphaned_folders(const fs::path& tmp) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(tmp, ec)) {
        if (!e.path().filename().string().starts_with(kFolderPrefix)) continue;
        struct stat st {};
        if (::lstat(e.path().c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != ::getuid()) continue;
        std::ifstream in(e.path() / "owner");
        long pid = 0;
        std::string start;
        if (!(in >> pid >> start) || pid <= 0) continue;
        if (process_start(pid) == start) continue;   // still running
        std::error_code gone;
        fs::remove_all(e.path(), gone);
    }
}

// A private folder for the effective settings the workers read, its owner written in it.
fs::path make_private_folder() {
    const char* tmp = std::getenv("TMPDIR");
    const fs::path dir = tmp && *tmp ? fs::path(tmp) : fs::path("/tmp");
    remove_orphaned_folders(dir);
    std::string pattern = (dir / kFolderPrefix).string() + "XXXXXX";
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot make a folder for the workers' settings in " + pattern);
    std::ofstream(fs::path(pattern) / "owner") << ::getpid() << ' ' << process_start(::getpid()) << '\n';
    return pattern;
}

// The job kind a HyperGP-family type's workers serve: its own name's, or its only one.
std::string job_kind_of(const io::Settings& s) {
    const experiments::ExperimentKind& kind = experiments::experiment_kind(s.experiment.type);
    if (kind.job_kinds.count(kind.type.name)) return kind.type.name;
    if (kind.job_kinds.size() == 1) return kind.job_kinds.begin()->first;
    throw InputError("experiment type '" + kind.type.name + "' serves no single job kind to evaluate genotypes with");
}

} // namespace

struct EvaluationSession::Impl {
    SessionOptions opt;
    fs::path found;
    io::Settings settings;
    fs::path folder;                       // the workers' settings.xml lives here
    GenotypeForm form = GenotypeForm::Vector;
    sim::Descriptor descriptor = sim::Descriptor::None;
    std::optional<gait::Setup> setup;      // gait family
    std::optional<hypergp::Model> model;   // HyperGP family
    std::optional<tree::PrimitiveSet> primitives;
    std::size_t offsets = 0;               // Offset-HybrID's per genotype, 0 without them
    std::string job_kind;
    std::unique_ptr<experiments::Context> ctx;
    std::unique_ptr<JobRunner> runner;
    bool closed = false;

    const sim::RobotSpec& robot() const { return setup ? setup->robot : model->robot; }

    // A gait vector: the gait family's genotype, or a Switch-HybrID run's after its hand-over.
    bool is_vector(const Genotype& g) const {
        return form == GenotypeForm::Vector || (setup && g.trees.empty() && !g.vector.empty());
    }

    // Throws InputError naming the genotype's place in the batch.
    void check(const Genotype& g, std::size_t index) const {
        const std::string who = fmt::format("genotype {}", index);
        if (is_vector(g)) {
            if (!g.offsets.empty())
                throw InputError(who + ": offsets are Offset-HybrID's direct genes beside HyperGP trees, not beside "
                                       "a gait vector");
            if (!g.trees.empty())
                throw InputError(who + ": these settings evolve " + settings.experiment.type +
                                 " vectors of numbers, not trees (S-expressions)");
            if (g.vector.size() != setup->dimension())
                throw InputError(fmt::format("{}: {} values, but these settings' {} has {} (robot {})", who,
                                             g.vector.size(), setup->cpg ? "CPG" : "gait", setup->dimension(),
                                             setup->robot.name));
            // The unit box; Switch-HybrID's centred gait has its phases and offsets in [-1/2, 1/2] (encoding.hpp).
            const std::vector<double> low =
                setup->cpg ? std::vector<double>(g.vector.size(), 0.0) : setup->encoding.lower();
            for (std::size_t i = 0; i < g.vector.size(); ++i)
                if (!std::isfinite(g.vector[i]) || g.vector[i] < low[i] || g.vector[i] > low[i] + 1.0)
                    throw InputError(fmt::format("{}: value {} is {}, outside the unit box [{}, {}] the gait family "
                                                 "searches", who, i, g.vector[i], low[i], low[i] + 1.0));
            return;
        }
        if (!g.vector.empty())
            throw InputError(who + ": these settings evolve HyperGP trees (S-expressions), not vectors of numbers");
        hypergp::check_offsets(*model, g.offsets, who);
        if (g.trees.size() != dimension())
            throw InputError(fmt::format("{}: {} tree{}, but GP.numberOfTreesInForestGenotype is {}", who,
                                         g.trees.size(), g.trees.size() == 1 ? "" : "s", dimension()));
    }

    tree::Forest forest_of(const Genotype& g, std::size_t index) const {
        tree::Forest f;
        for (std::size_t t = 0; t < g.trees.size(); ++t) {
            try {
                f.push_back(tree::Tree::parse(g.trees[t], &*primitives));
            } catch (const InputError& e) {
                throw InputError(fmt::format("genotype {}, tree {}: {}", index, t, e.message()));
            }
        }
        return f;
    }

    std::size_t dimension() const {
        return form == GenotypeForm::Vector ? setup->dimension()
                                            : static_cast<std::size_t>(settings.gp.trees_per_genotype);
    }
};

EvaluationSession::EvaluationSession(SessionOptions options) : impl_(std::make_unique<Impl>()) {
    Impl& im = *impl_;
    im.opt = std::move(options);
    if (im.opt.workers < 1) throw InputError(fmt::format("workers must be at least 1, got {}", im.opt.workers));
    // As given, else among the installed settings beside the worker binary.
    im.found = find_settings_file(im.opt.settings_file, im.opt.worker_executable, im.opt.note);
    im.settings = io::load_settings(im.found, im.opt.overrides);
    const io::Settings& s = im.settings;
    if (!io::walks_a_robot(s))
        throw InputError("scores robot experiments (HyperGP, gait, CPG and their types); these settings are symbolic "
                         "regression (Experiment.type " + s.experiment.type + ")", im.found.string());
    experiments::check_inputs(s);   // the robot and every input a run of them reads
    if (s.map_elites.enabled) im.descriptor = s.map_elites.descriptor;
    if (io::genotype_form(s) == io::GenotypeForm::Vector) {
        im.form = GenotypeForm::Vector;
        im.setup.emplace(gait::Setup::from_settings(s));
    } else {
        im.form = GenotypeForm::Forest;
        im.model.emplace(hypergp::Model::from_settings(s));
        // Switch-HybrID: its trees hand over to IPOP-CMA-ES on the gait vector, so both are its genotypes.
        if (s.neural.switches()) im.setup.emplace(gait::Setup::from_settings(s));
        im.offsets = hypergp::direct_offset_genes(*im.model).count;
        im.primitives.emplace(s.gp.primitives);
        im.job_kind = job_kind_of(s);
    }
    im.folder = make_private_folder();
    try {
        const fs::path effective = im.folder / "settings.xml";
        io::xml::write_file_atomically(effective, io::write_settings(s));
        const fs::path base = s.source_file.empty() ? fs::current_path() : fs::path(s.source_file).parent_path();
        im.ctx = std::make_unique<experiments::Context>(
            experiments::Context{s, base, effective, im.opt.worker_executable, im.opt.workers});
        im.ctx->warn = im.opt.warn;
        im.ctx->interrupted = im.opt.interrupted;
        // The workers start with the first batch (simulate() needs none); a
        // binary that cannot serve them is said now.
        if (::access(im.opt.worker_executable.c_str(), X_OK) != 0)
            throw std::runtime_error("cannot execute the cic binary for worker processes: '" +
                                     im.opt.worker_executable + "'");
    } catch (...) {
        std::error_code ec;
        fs::remove_all(im.folder, ec);
        throw;
    }
}

EvaluationSession::~EvaluationSession() { close(); }

void EvaluationSession::close() {
    Impl& im = *impl_;
    if (im.closed) return;
    im.closed = true;
    im.runner.reset();   // ends the workers
    std::error_code ec;
    fs::remove_all(im.folder, ec);
}

const io::Settings& EvaluationSession::settings() const { return impl_->settings; }
fs::path EvaluationSession::settings_file() const { return impl_->found; }
GenotypeForm EvaluationSession::form() const { return impl_->form; }
std::size_t EvaluationSession::dimension() const { return impl_->dimension(); }
std::size_t EvaluationSession::offsets() const { return impl_->offsets; }
std::size_t EvaluationSession::vector_dimension() const { return impl_->setup ? impl_->setup->dimension() : 0; }
int EvaluationSession::workers() const { return impl_->opt.workers; }

void EvaluationSession::check(const Genotype& g, std::size_t index) const {
    impl_->check(g, index);
    if (impl_->form == GenotypeForm::Forest) (void)impl_->forest_of(g, index);
}

Scores EvaluationSession::evaluate(const std::vector<Genotype>& batch) {
    Impl& im = *impl_;
    if (im.closed) throw std::runtime_error("the evaluator is closed");
    for (std::size_t i = 0; i < batch.size(); ++i) check(batch[i], i);
    Scores out;
    if (batch.empty()) return out;
    // One job per genotype, as a run writes it (gait::make_job, hypergp::job_body), all
    // parsed first so a bad tree fails the batch before it runs, then one pass of the workers.
    std::vector<std::string> jobs;
    std::vector<double> failure_fitness;
    for (std::size_t i = 0; i < batch.size(); ++i) {
        if (im.is_vector(batch[i])) {
            jobs.push_back(gait::make_job(*im.setup, batch[i].vector, im.descriptor));
            failure_fitness.push_back(im.setup->sim.failure_fitness);
        } else {
            jobs.push_back(im.job_kind + "\n" +
                           hypergp::job_body(im.forest_of(batch[i], i), im.descriptor, batch[i].offsets));
            failure_fitness.push_back(im.model->sim.failure_fitness);
        }
    }
    if (!im.runner) im.runner = experiments::make_job_runner(*im.ctx);
    const std::vector<JobResult> results = im.runner->run(jobs);
    for (const auto& note : im.runner->take_notes()) im.opt.warn("warning: " + note);
    std::vector<sim::EvalReply> replies;
    for (std::size_t i = 0; i < results.size(); ++i) {
        const JobResult& r = results[i];
        for (const auto& t : r.trouble) im.opt.warn(fmt::format("warning: genotype {}: {}", i, t));
        replies.push_back(sim::reply_of(r, failure_fitness[i]));   // as a run scores it
        if (!r.ok)
            im.opt.warn(fmt::format("warning: genotype {} scored as failed (fitness {}): {}", i, failure_fitness[i],
                                    r.error));
    }
    for (sim::EvalReply& r : replies) {
        out.fitness.push_back(r.fitness);
        out.distance.push_back(r.distance);
        out.elevation.push_back(r.elevation);
        out.descriptor.push_back(std::move(r.descriptor));
        out.failed.push_back(r.failed ? 1 : 0);
        out.failure.push_back(std::move(r.failure));
    }
    return out;
}

Walk EvaluationSession::simulate(const Genotype& g, bool trace) const {
    const Impl& im = *impl_;
    im.check(g, 0);
    sim::EvalOptions options;
    options.record_trace = trace;
    options.record_ground = trace || sim::needs_ground(im.descriptor);
    Walk w;
    sim::EvalResult r;
    if (im.is_vector(g)) {
        const auto controller = im.setup->controller(g.vector);
        r = sim::evaluate(im.setup->robot, *controller, im.setup->sim, options);
        w.fitness = r.fitness;
    } else {
        hypergp::Outcome o =
            experiments::evaluate_as_type(*im.model, im.settings, im.forest_of(g, 0), options, false, g.offsets);
        w.fitness = o.fitness;   // as the run scores it: the penalty, or a registered type's own score
        r = std::move(o.result);
    }
    const sim::RobotSpec& robot = im.robot();
    w.failed = r.failed;
    w.failure = r.failure;
    if (!r.failed) std::tie(w.distance, w.elevation) = sim::walk_terms(robot, r);
    w.joint_names = sim::joint_names(robot);
    w.foot_names = sim::foot_names(robot);
    for (const sim::TraceRow& row : r.trace) {
        w.time.push_back(row.t);
        w.centre.insert(w.centre.end(), row.centre.begin(), row.centre.end());
        w.angles.insert(w.angles.end(), row.actual.begin(), row.actual.end());
        w.targets.insert(w.targets.end(), row.desired.begin(), row.desired.end());
        w.feet.insert(w.feet.end(), row.feet_on_ground.begin(), row.feet_on_ground.end());
    }
    if (trace) w.duty_factors = sim::duty_factors(robot, r);   // assess's count, from the delayed start on
    return w;
}

std::vector<double> EvaluationSession::in_box(const std::vector<double>& x, BoxReading reading) const {
    const Impl& im = *impl_;
    if (!im.setup)
        throw InputError("these settings evolve HyperGP trees: there is no gait vector to read into the unit box");
    if (x.size() != im.setup->dimension())
        throw InputError(fmt::format("{} values, but these settings' {} has {} (robot {})", x.size(),
                                     im.setup->cpg ? "CPG" : "gait", im.setup->dimension(), im.setup->robot.name));
    for (std::size_t i = 0; i < x.size(); ++i)
        if (!std::isfinite(x[i])) throw InputError(fmt::format("value {} is {}: not a number to read", i, x[i]));
    gait::Setup setup = *im.setup;
    if (reading != BoxReading::Settings) {
        const gait::Bounds b = reading == BoxReading::Reflect ? gait::Bounds::Reflect : gait::Bounds::Clamp;
        setup.encoding.bounds = b;
        if (setup.cpg) setup.cpg->bounds = b;
    }
    return setup.in_box(x);
}

sim::GaitSpec EvaluationSession::decode(const std::vector<double>& x) const {
    const Impl& im = *impl_;
    if (!im.setup) throw InputError("these settings evolve HyperGP trees: there is no gait vector to decode");
    if (im.setup->cpg)
        throw InputError("these settings' gait vector holds CPG weights (Gait.controller = cpg), not a sine gait");
    check(Genotype{x, {}, {}}, 0);   // the unit box, as evaluate takes it
    return im.setup->encoding.decode(x);
}

std::vector<std::string> EvaluationSession::joint_names() const { return sim::joint_names(impl_->robot()); }

RunBest read_run_best(const fs::path& run_dir) {
    const report::RunGenotype g = report::read_run_genotype(run_dir.string());
    RunBest best;
    best.settings = run_dir / "settings.xml";
    best.fitness = g.stored_fitness;
    best.generation = g.generation;
    best.form = g.trees.empty() ? GenotypeForm::Vector : GenotypeForm::Forest;
    // The optimiser may store a point outside the unit box: the session takes the one that decodes alike.
    if (best.form == GenotypeForm::Vector) best.genotype.vector = gait::Setup::from_settings(g.settings).in_box(g.gait);
    for (const auto& t : g.trees) best.genotype.trees.push_back(t.to_string());
    best.genotype.offsets = g.offsets;   // Offset-HybrID's, empty otherwise
    return best;
}

} // namespace cic::run
