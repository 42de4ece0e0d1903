// Replays saved HyperGP individuals with the evaluation's own code path
// (hypergp::run), for the viewer, POV-Ray export and traces.
#include "cic/report/replay.hpp"
#include "cic/io/experiment_types.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <sstream>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/io/xml.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/sim/layout.hpp"
#include "cic/io/archive_xml.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/report/plot.hpp"
#include "cic/experiments/map_elites_grid.hpp"
#include "cic/experiments/gait/setup.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/experiments/registry.hpp"
#include "replay_support.hpp"

namespace cic::report {
namespace fs = std::filesystem;

namespace detail {

int centre_body_of(const sim::RobotSpec& robot) {
    const sim::BodyLayout layout = sim::make_body_layout(robot);
    return layout.geoms[static_cast<std::size_t>(layout.chassis_geom[static_cast<std::size_t>(robot.centre)])].body;
}

// One gait vector of the settings' gait, walked and recorded.
ReplayItem replay_point(const gait::Setup& setup, const std::vector<double>& x, double fps, bool trace,
                        sim::Descriptor descriptor) {
    const std::unique_ptr<sim::Controller> controller = setup.controller(x);
    sim::EvalOptions opt;
    opt.record_fps = fps;
    opt.record_trace = trace;
    opt.record_ground = trace || sim::needs_ground(descriptor);
    sim::EvalResult r = sim::evaluate(setup.robot, *controller, setup.sim, opt);
    ReplayItem item;
    if (r.recording) item.recording = *r.recording;
    item.trace = r.trace;
    if (trace)
        for (const auto& row : item.trace) item.raw_outputs.push_back(row.desired);   // open loop: the commands
    item.replayed_fitness = r.fitness;
    item.raw_fitness = r.fitness;   // no penalty on a gait
    item.centre_body = centre_body_of(setup.robot);
    item.joint_names = sim::joint_names(setup.robot);
    fill_walk(item, setup.robot, r);
    if (!r.failed) item.descriptor = sim::descriptor_of(descriptor, setup.robot, r);
    return item;
}

// One HyperGP genotype (with its direct genes, if any), scored as the run's type
// scores it (a registered type's own fitness), eq. 7.1 beside it, and recorded.
ReplayItem replay_trees(const hypergp::Model& model, const io::Settings& settings, const tree::Forest& genotype,
                        std::span<const double> offsets, double fps, bool trace, sim::Descriptor descriptor) {
    sim::EvalOptions opt;
    opt.record_fps = fps;
    opt.record_trace = trace;
    opt.record_ground = trace || sim::needs_ground(descriptor);
    const hypergp::Outcome o = experiments::evaluate_as_type(model, settings, genotype, opt, trace, offsets);
    ReplayItem item;
    if (o.result.recording) item.recording = *o.result.recording;
    item.trace = o.result.trace;
    if (trace) {
        const std::size_t j = o.control.joints;
        for (std::size_t step = 0; step < o.control.steps(); ++step)
            item.raw_outputs.emplace_back(o.control.outputs.begin() + static_cast<std::ptrdiff_t>(step * j),
                                          o.control.outputs.begin() + static_cast<std::ptrdiff_t>((step + 1) * j));
    }
    item.replayed_fitness = o.fitness;
    item.raw_fitness = o.distance_fitness;
    item.centre_body = centre_body_of(model.robot);
    item.joint_names = sim::joint_names(model.robot);
    fill_walk(item, model.robot, o.result);
    if (!o.failed) item.descriptor = sim::descriptor_of(descriptor, model.robot, o.result);
    return item;
}

} // namespace detail

using detail::replay_point;
using detail::replay_trees;
using detail::centre_body_of;

namespace {

// The run folder's settings.xml, found from a run folder or a population file in it.
struct Source {
    fs::path population;
    fs::path settings;
};

Source locate(const std::string& what) {
    const fs::path p(what);
    if (!fs::exists(p)) throw InputError("no such run folder or population file", what);
    Source s;
    if (fs::is_directory(p)) {
        s.population = p / "population.xml";
        s.settings = p / "settings.xml";
        if (!fs::exists(s.population)) throw InputError("run folder has no population.xml (has the run written a generation yet?)", what);
    } else {
        s.population = p;
        for (fs::path dir = p.parent_path(); !dir.empty(); dir = dir.parent_path()) {
            if (fs::exists(dir / "settings.xml")) {
                s.settings = dir / "settings.xml";
                break;
            }
            if (dir == dir.parent_path()) break;
        }
    }
    if (s.settings.empty() || !fs::exists(s.settings))
        throw InputError("cannot find the run's settings.xml next to the population file or in a folder above it", what);
    return s;
}

std::map<std::string, CheckpointBestReader>& checkpoint_readers() {
    static std::map<std::string, CheckpointBestReader> r;
    return r;
}

// The root element of a checkpoint file, to find a registered reader.
std::string root_of(const fs::path& file) {
    try {
        return std::string(io::xml::Document::load_file(file).root().name());
    } catch (const InputError&) {
        return {};   // the built-in readers say what is wrong with it
    }
}

// A checkpoint of a search registered from outside: its reader gives the best
// gait, or the best trees of a search of trees.
std::vector<ReplayItem> replay_foreign(const Source& src, const io::Settings& settings, const std::string& individual,
                                       const CheckpointBestReader& reader, double fps, bool trace) {
    if (individual != "best")
        throw InputError("this run's checkpoint keeps one individual to replay: use --individual best",
                         src.population.string());
    const CheckpointBest best = read_checkpoint_best(reader, settings, src.population.string());
    ReplayItem item = best.trees.empty()
                          ? replay_point(gait::Setup::from_settings(settings), best.x, fps, trace)
                          : replay_trees(hypergp::Model::from_settings(settings), settings, best.trees, best.x, fps,
                                         trace);
    item.label = fmt::format("{}, found in generation {}", best.who, best.generation);
    item.who = best.who;
    item.stored_fitness = best.fitness;
    item.generation = best.generation;
    return {std::move(item)};
}

// A gait run: its best gait so far (the checkpoint's champion) is the one replay.
std::vector<ReplayItem> replay_gait(const Source& src, const io::Settings& settings, const std::string& individual,
                                    double fps, bool trace) {
    if (individual != "best")
        throw InputError("a gait run keeps one gait to replay: use --individual best", src.population.string());
    const gait::Setup setup = gait::Setup::from_settings(settings);
    const io::GaitFile g = io::load_gait(src.population);
    io::check_compatible(g, settings, setup.dimension(), src.population.string());
    ReplayItem item = replay_point(setup, g.champion.x, fps, trace);
    // The champion was found in the first generation whose best so far reached it.
    int found = -1;
    try {
        for (const StatsRow& row : read_stats_csv(src.settings.parent_path() / "stats.csv"))
            if (row.generation <= g.generation && row.best_so_far >= g.champion.fitness) {
                found = row.generation;
                break;
            }
    } catch (const InputError&) {
        // no statistics beside the checkpoint: say only what the checkpoint knows
    }
    item.label = found >= 0 ? fmt::format("best {} gait, found in generation {} (of 0 to {})", g.optimizer, found,
                                          g.generation)
                            : fmt::format("best {} gait of generations 0 to {}", g.optimizer, g.generation);
    item.who = fmt::format("best {} gait", g.optimizer);
    item.stored_fitness = g.champion.fitness;
    item.generation = found >= 0 ? found : g.generation;
    return {std::move(item)};
}

// The cell a --cell text names: "I,J,..." (one bin per dimension) or a number.
std::size_t cell_named(const std::string& text, const gp::GridSpec& grid, const std::string& file) {
    std::vector<long> parts;
    std::string item;
    std::istringstream in(text);
    while (std::getline(in, item, ',')) {
        std::size_t used = 0;
        long v = -1;
        try {
            v = std::stol(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != item.size() || v < 0)
            throw InputError("--cell takes I,J,... (a bin per descriptor dimension, from 0) or a cell number; got '" +
                             text + "'");
        parts.push_back(v);
    }
    if (parts.size() == 1 && grid.dimensions() > 1) {
        if (static_cast<std::size_t>(parts[0]) >= grid.cells())
            throw InputError(fmt::format("--cell {}: the grid has cells 0 to {}", text, grid.cells() - 1), file);
        return static_cast<std::size_t>(parts[0]);
    }
    if (parts.size() != grid.dimensions())
        throw InputError(fmt::format("--cell {}: the grid has {} dimensions, so give {} bins", text, grid.dimensions(),
                                     grid.dimensions()),
                         file);
    std::size_t cell = 0;
    for (std::size_t d = 0; d < parts.size(); ++d) {
        if (parts[d] >= grid.bins[d])
            throw InputError(fmt::format("--cell {}: dimension {} has bins 0 to {}", text, d + 1, grid.bins[d] - 1),
                             file);
        cell = cell * static_cast<std::size_t>(grid.bins[d]) + static_cast<std::size_t>(parts[d]);
    }
    return cell;
}

// A MAP-Elites run: the fittest elites, or the one of a cell.
std::vector<ReplayItem> replay_archive(const Source& src, const io::Settings& settings, const std::string& individual,
                                       int count, double fps, bool trace) {
    const io::ArchiveFile a = io::load_archive(src.population);
    // The family's own setup, which reads the robot once.
    const bool gait = io::family_of(settings) == io::ExperimentFamily::Gait;
    std::optional<gait::Setup> setup;
    std::optional<hypergp::Model> model;
    if (gait)
        setup.emplace(gait::Setup::from_settings(settings));
    else
        model.emplace(hypergp::Model::from_settings(settings));
    const sim::RobotSpec& robot = gait ? setup->robot : model->robot;
    io::check_compatible(a, settings, experiments::map_elites_grid(settings, robot), gait ? setup->dimension() : 0,
                         src.population.string());
    std::vector<const io::ArchiveElite*> chosen;
    if (individual == "best") {
        for (const auto& e : a.elites) chosen.push_back(&e);
        std::stable_sort(chosen.begin(), chosen.end(), [](auto* x, auto* y) { return x->fitness > y->fitness; });
        chosen.resize(std::min<std::size_t>(chosen.size(), static_cast<std::size_t>(std::max(1, count))));
        if (chosen.empty()) throw InputError("the archive holds no elite (every evaluation failed)", src.population.string());
    } else if (individual.rfind("cell:", 0) == 0) {
        const std::size_t cell = cell_named(individual.substr(5), a.grid, src.population.string());
        const io::ArchiveElite* e = a.at(cell);
        if (!e)
            throw InputError(fmt::format("cell {} ({}) is empty: {} of {} cells hold an elite (cic export lists them)",
                                         a.grid.cell_name(cell), cell, a.elites.size(), a.grid.cells()),
                             src.population.string());
        chosen.push_back(e);
    } else {
        throw InputError("a MAP-Elites run's elites are chosen by --cell I,J,... or --individual best, not an id; got '" +
                         individual + "'");
    }
    std::vector<ReplayItem> items;
    for (const io::ArchiveElite* e : chosen) {
        if (gait && e->x.size() != setup->dimension())
            throw InputError(fmt::format("the elite of cell {} has {} parameters, these settings make {}", e->cell,
                                         e->x.size(), setup->dimension()),
                             src.population.string());
        ReplayItem item = gait ? replay_point(*setup, e->x, fps, trace)
                               : replay_trees(*model, settings, e->genotype, {}, fps, trace);
        item.label = fmt::format("cell {} ({}), batch {}", a.grid.cell_name(e->cell), e->cell, a.batches - 1);
        item.stored_fitness = e->fitness;
        item.generation = a.batches - 1;
        item.id = e->cell;
        item.elite = true;
        items.push_back(std::move(item));
    }
    return items;
}

} // namespace

std::pair<double, double> eq71_terms(const sim::RobotSpec& robot, const sim::EvalResult& r) {
    return sim::walk_terms(robot, r);
}

// Eq. 7.1's terms and, when the ground was recorded, each foot's duty factor.
void fill_walk(ReplayItem& item, const sim::RobotSpec& robot, const sim::EvalResult& r) {
    std::tie(item.distance, item.elevation) = eq71_terms(robot, r);
    item.preferred_axis = robot.preferred == sim::Axis::X ? 0 : 1;
    for (std::size_t k = 0; k < 3; ++k) {
        item.measured_from[k] = r.start[k];
        item.measured_to[k] = r.end[k];
    }
    if (r.module_ground_steps.empty()) return;
    item.duty_factors = sim::duty_factors(robot, r);
    item.foot_names = sim::foot_names(robot);
}

ReplayItem replay_genotype(const io::Settings& settings, const tree::Forest& genotype,
                           std::span<const double> offsets, double fps, bool trace) {
    return replay_trees(hypergp::Model::from_settings(settings), settings, genotype, offsets, fps, trace);
}

ReplayItem replay_gait_vector(const io::Settings& settings, const std::vector<double>& x, double fps, bool trace) {
    const gait::Setup setup = gait::Setup::from_settings(settings);
    if (x.size() != setup.dimension())
        throw InputError(fmt::format("a gait of {} numbers, but these settings' gait has {}", x.size(),
                                     setup.dimension()));
    return replay_point(setup, x, fps, trace);
}

void register_checkpoint_reader(std::string root, CheckpointBestReader reader) {
    for (const char* own : {"population", "gaitRun", "archive"})
        if (root == own) throw std::invalid_argument("checkpoint root <" + root + "> is cic's own");
    if (root.empty() || !reader) throw std::invalid_argument("a checkpoint reader needs a root element and a reader");
    if (!checkpoint_readers().emplace(root, std::move(reader)).second)
        throw std::invalid_argument("checkpoint root <" + root + "> has a reader already");
}

CheckpointBest read_checkpoint_best(const CheckpointBestReader& reader, const io::Settings& s, const std::string& file) {
    CheckpointBest best = reader(s, file);
    if (best.trees.empty()) {
        // Switch-HybrID's genotypes are gait vectors after its hand-over.
        if (io::genotype_form(s) != io::GenotypeForm::Vector && !s.neural.switches())
            throw InputError(fmt::format("the checkpoint's reader gave a gait vector, but Experiment.type {} evolves "
                                         "HyperGP trees",
                                         s.experiment.type),
                             file);
        const std::size_t want = gait::Setup::from_settings(s).dimension();
        if (best.x.size() != want)
            throw InputError(fmt::format("the checkpoint's reader gave a gait of {} numbers, but these settings' gait "
                                         "has {}",
                                         best.x.size(), want),
                             file);
        return best;
    }
    if (io::family_of(s) != io::ExperimentFamily::HyperGP)
        throw InputError(fmt::format("the checkpoint's reader gave trees, but Experiment.type {} does not walk a "
                                     "HyperGP genotype",
                                     s.experiment.type),
                         file);
    if (best.trees.size() != static_cast<std::size_t>(s.gp.trees_per_genotype))
        throw InputError(fmt::format("the checkpoint's reader gave {} trees, but GP.numberOfTreesInForestGenotype is {}",
                                     best.trees.size(), s.gp.trees_per_genotype),
                         file);
    hypergp::check_offsets(hypergp::Model::from_settings(s), best.x, "the checkpoint's best", file);
    return best;
}

const CheckpointBestReader* checkpoint_reader_for(const std::string& file) {
    if (checkpoint_readers().empty()) return nullptr;
    const auto it = checkpoint_readers().find(root_of(file));
    return it == checkpoint_readers().end() ? nullptr : &it->second;
}

std::vector<ReplayItem> replay(const std::string& source, const std::string& individual, int count, double fps,
                               bool trace) {
    const Source src = locate(source);
    const io::Settings settings = io::read_settings(src.settings);
    if (const CheckpointBestReader* reader = checkpoint_reader_for(src.population.string()))
        return replay_foreign(src, settings, individual, *reader, fps, trace);   // a registered search's own file
    if (settings.map_elites.enabled) return replay_archive(src, settings, individual, count, fps, trace);
    if (individual.rfind("cell:", 0) == 0)
        throw InputError("--cell picks an elite of a MAP-Elites run (MapElites.enabled); this run has no archive",
                         src.settings.string());
    // A Switch-HybrID run past its hand-over keeps its best in a gait checkpoint.
    if (io::family_of(settings) == io::ExperimentFamily::Gait ||
        (settings.neural.switches() && io::is_gait_file(src.population)))
        return replay_gait(src, settings, individual, fps, trace);
    if (io::family_of(settings) != io::ExperimentFamily::HyperGP)
        throw InputError("only robot runs (HyperGP, gait) can be replayed; this run is symbolic regression",
                         src.settings.string());
    const io::PopulationFile pop = io::load_population(src.population);
    io::check_compatible(pop, settings, src.population.string());

    std::vector<gp::IndividualPtr> chosen;
    if (individual == "best") {
        chosen = pop.population.individuals;
        std::sort(chosen.begin(), chosen.end(), [](const auto& a, const auto& b) { return gp::better(*a, *b); });
        chosen.resize(std::min<std::size_t>(chosen.size(), static_cast<std::size_t>(std::max(1, count))));
    } else {
        std::uint64_t id = 0;
        try {
            std::size_t used = 0;
            id = std::stoull(individual, &used);
            if (used != individual.size()) throw std::invalid_argument(individual);
        } catch (const std::exception&) {
            throw InputError("--individual must be 'best' or an individual id, got '" + individual + "'");
        }
        for (const auto& ind : pop.population)
            if (ind->id == id) chosen.push_back(ind);
        if (chosen.empty()) throw InputError(fmt::format("no individual with id {} in this population", id), src.population.string());
    }

    // A growing robot's population is replayed on the body it was evaluated on;
    // with several bodies, on the robot alone (its eq. 7.1, beside the aggregate).
    const hypergp::Model model = hypergp::Model::from_settings(settings).on_body(pop.body.value_or(0));
    std::vector<ReplayItem> items;
    for (const auto& ind : chosen) {
        ReplayItem item = replay_trees(model, settings, ind->genotype, ind->direct, fps, trace);
        item.label = fmt::format("generation {}, individual {}", pop.population.generation, ind->id);
        item.stored_fitness = ind->fitness;
        item.generation = pop.population.generation;
        item.id = ind->id;
        items.push_back(std::move(item));
    }
    return items;
}

} // namespace cic::report
