// Replays saved HyperGP individuals with the evaluation's own code path
// (hypergp::run), for the viewer, POV-Ray export and traces.
#include "cic/report/replay.hpp"
#include "cic/io/experiment_types.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <filesystem>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/sim/layout.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/experiments/gait/setup.hpp"
#include "cic/experiments/hypergp/model.hpp"

namespace cic::app {
namespace fs = std::filesystem;

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

std::vector<std::string> joint_names_of(const sim::RobotSpec& robot) {
    std::vector<std::string> names;
    for (int m : robot.actuated()) {
        const auto& mod = robot.modules[static_cast<std::size_t>(m)];
        names.push_back(mod.name.empty() ? fmt::format("m{}", m) : mod.name);
    }
    return names;
}

int centre_body_of(const sim::RobotSpec& robot) {
    const sim::BodyLayout layout = sim::make_body_layout(robot);
    return layout.geoms[static_cast<std::size_t>(layout.chassis_geom[static_cast<std::size_t>(robot.centre)])].body;
}

// A gait run: its best gait so far (the checkpoint's champion) is the one replay.
std::vector<ReplayItem> replay_gait(const Source& src, const io::Settings& settings, const std::string& individual,
                                    double fps, bool trace) {
    if (individual != "best")
        throw InputError("a gait run keeps one gait to replay: use --individual best", src.population.string());
    const gait::Setup setup = gait::Setup::from_settings(settings);
    const io::GaitFile g = io::load_gait(src.population);
    io::check_compatible(g, settings, setup.dimension(), src.population.string());
    const std::unique_ptr<sim::Controller> controller = setup.controller(g.champion.x);
    sim::EvalOptions opt;
    opt.record_fps = fps;
    opt.record_trace = trace;
    opt.record_ground = trace;
    sim::EvalResult r = sim::evaluate(setup.robot, *controller, setup.sim, opt);
    ReplayItem item;
    item.label = fmt::format("generation {}, best {} gait", g.generation, g.optimizer);
    item.stored_fitness = g.champion.fitness;
    item.generation = g.generation;
    if (r.recording) item.recording = *r.recording;
    item.trace = r.trace;
    if (trace)
        for (const auto& row : item.trace) item.raw_outputs.push_back(row.desired);   // open loop: the commands
    item.replayed_fitness = r.fitness;
    item.raw_fitness = r.fitness;   // no penalty in the gait experiment
    item.centre_body = centre_body_of(setup.robot);
    item.joint_names = joint_names_of(setup.robot);
    fill_walk(item, setup.robot, r);
    return {std::move(item)};
}

} // namespace

std::pair<double, double> eq71_terms(const sim::RobotSpec& robot, const sim::EvalResult& r) {
    const std::size_t p = robot.preferred == sim::Axis::X ? 0 : 1;
    return {std::fabs(r.end[p] - r.start[p]), r.end[2] - r.start[2]};
}

// Eq. 7.1's terms and, when the ground was recorded, each foot's duty factor.
void fill_walk(ReplayItem& item, const sim::RobotSpec& robot, const sim::EvalResult& r) {
    std::tie(item.distance, item.elevation) = eq71_terms(robot, r);
    if (r.module_ground_steps.empty()) return;
    item.duty_factors = sim::duty_factors(robot, r);
    for (int m : sim::branch_ends(robot)) {
        const std::string& name = robot.modules[static_cast<std::size_t>(m)].name;
        item.foot_names.push_back(name.empty() ? "m" + std::to_string(m) : name);
    }
}

std::vector<ReplayItem> replay(const std::string& source, const std::string& individual, int count, double fps,
                               bool trace) {
    const Source src = locate(source);
    const io::Settings settings = io::read_settings(src.settings);
    if (io::family_of(settings) == io::ExperimentFamily::Gait) return replay_gait(src, settings, individual, fps, trace);
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

    const hypergp::Model model = hypergp::Model::from_settings(settings);
    const int centre_body = centre_body_of(model.robot);
    const std::vector<std::string> joint_names = joint_names_of(model.robot);

    std::vector<ReplayItem> items;
    for (const auto& ind : chosen) {
        sim::EvalOptions opt;
        opt.record_fps = fps;
        opt.record_trace = trace;
        opt.record_ground = trace;
        const hypergp::Outcome o = hypergp::run(model, ind->genotype, opt, trace);
        ReplayItem item;
        item.label = fmt::format("generation {}, individual {}", pop.population.generation, ind->id);
        item.stored_fitness = ind->fitness;
        item.generation = pop.population.generation;
        item.id = ind->id;
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
        item.centre_body = centre_body;
        item.joint_names = joint_names;
        fill_walk(item, model.robot, o.result);
        items.push_back(std::move(item));
    }
    return items;
}

} // namespace cic::app
