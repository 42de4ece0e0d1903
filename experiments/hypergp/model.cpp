#include "cic/experiments/hypergp/model.hpp"
#include "cic/experiments/map_elites_grid.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cic/core/error.hpp"
#include "cic/core/limits.hpp"
#include "cic/io/robot_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/experiments/hypergp/gait_substrate.hpp"
#include "cic/sim/controller.hpp"
#include "cic/sim/evaluate.hpp"
#include "cic/experiments/hypergp/oscillation.hpp"
#include "cic/experiments/hypergp/substrate_geometry.hpp"

namespace cic::hypergp {

Model Model::from_settings(const io::Settings& s) {
    Model m;
    m.robot = s.robot.robot_file.empty() ? sim::preset(s.robot.robot_type, s.neural.middle_legs)
                                         : io::read_robot_file(s.robot.robot_file);
    m.robot.validate();
    m.sim = s.sim;
    m.neural = s.neural;
    for (const auto& file : s.robot.extra_robot_files) m.extra_robots.push_back(io::read_robot_file(file));
    m.aggregate = s.robot.bodies_aggregate;
    for (const auto& file : s.robot.grow_robot_files) m.grow_robots.push_back(io::read_robot_file(file));
    return m;
}

Model Model::on_body(std::size_t body) const {
    if (body > grow_robots.size())
        throw std::out_of_range(fmt::format("body {} of a robot that grows through {} bodies", body,
                                            grow_robots.size() + 1));
    Model m = *this;
    if (body > 0) m.robot = grow_robots[body - 1];
    return m;
}

void check_first_step(const sim::RobotSpec& robot, const sim::SimConfig& config, const std::string& where) {
    // One control step of a still controller: a robot or simulator whose
    // physics cannot even start (coordinates far out, a blow-up at t = 0)
    // would fail every evaluation, and the run would end with the failure
    // fitness as its best. Cheap: one world and one step.
    sim::SimConfig probe = config;
    probe.sample_to = probe.sample_from + probe.sample_step;
    probe.delayed_start = probe.sample_from;
    sim::ConstantController still(0.0);
    const sim::EvalResult r = sim::evaluate(robot, still, probe);
    if (r.failed)
        throw InputError("robot '" + robot.name + "' cannot be simulated: its physics fails at the first step (a "
                         "test evaluation with every joint held at 0): " + r.failure, where);
}

namespace {

// One body's checks: at least one joint, physics that starts, a substrate
// within the limits.
void check_body(const Model& m, const io::Settings& s, const std::string& where);

} // namespace

void check_inputs(const io::Settings& s) {
    // Each robot file on its own first, so that an error names its key.
    auto read = [](const std::string& file, const std::string& key) {
        try {
            io::read_robot_file(file).validate();
        } catch (const InputError& e) {
            throw InputError("<Simulator> " + key + ": " + e.message(), e.file(), e.line());
        }
    };
    if (!s.robot.robot_file.empty()) read(s.robot.robot_file, "robotFile");
    for (const auto& f : s.robot.extra_robot_files) read(f, "extraRobotFiles");
    for (const auto& f : s.robot.grow_robot_files) read(f, "growRobotFiles");
    const Model m = Model::from_settings(s);
    const std::string where = s.robot.robot_file.empty()
        ? "<Simulator> robot_type = " + std::to_string(s.robot.robot_type)
        : s.robot.robot_file + ": <Simulator> robotFile";
    check_body(m, s, where);
    for (std::size_t i = 0; i < m.extra_robots.size(); ++i) {
        Model body = m;
        body.robot = m.extra_robots[i];
        check_body(body, s, s.robot.extra_robot_files[i] + ": <Simulator> extraRobotFiles");
    }
    for (std::size_t k = 1; k <= m.grow_robots.size(); ++k)
        check_body(m.on_body(k), s, s.robot.grow_robot_files[k - 1] + ": <Simulator> growRobotFiles");
}

namespace {

void check_body(const Model& m, const io::Settings& s, const std::string& where) {
    if (m.robot.actuated().empty())
        throw InputError("robot '" + m.robot.name + "' has no joint (every module is fixed): HyperGP needs at "
                         "least one module with axis x, y or z", where);
    check_first_step(m.robot, m.sim, where);
    if (s.map_elites.enabled) (void)experiments::map_elites_grid(s, m.robot);
    if (m.neural.substrate != "network") return;   // the limits below are the network's
    const nn::NeuronLayout layout = nn::make_neuron_layout(substrate_geometry(m.robot, m.neural), m.neural);
    const std::size_t in = layout.input.size(), hidden = layout.hidden.size(), out = layout.output.size();
    if (in + hidden + out > limits::kMaxNeurons)
        throw InputError("robot '" + m.robot.name + "' gives a substrate of " + std::to_string(in + hidden + out) +
                         " neurons, past the limit of " + std::to_string(limits::kMaxNeurons), where);
    // Potential synapses of the enabled types (ih ho hh oo oh), as nn::SynapseType orders them.
    const std::size_t per_type[] = {in * hidden, hidden * out, hidden * hidden, out * out, out * hidden};
    std::size_t synapses = 0;
    for (std::size_t t = 0; t < std::size(per_type); ++t)
        if (t < m.neural.synapse_enabled.size() && m.neural.synapse_enabled[t]) synapses += per_type[t];
    if (synapses > limits::kMaxSynapses)
        throw InputError("robot '" + m.robot.name + "' gives a substrate of " + std::to_string(synapses) +
                         " potential synapses, past the limit of " + std::to_string(limits::kMaxSynapses), where);
}

} // namespace

Outcome run(const Model& m, const tree::Forest& genotype, const sim::EvalOptions& options, bool record_control) {
    return run(m, genotype, {}, options, record_control);
}

Outcome run(const Model& m, const tree::Forest& genotype, std::span<const double> offsets,
            const sim::EvalOptions& options, bool record_control) {
    Outcome o;
    const std::unique_ptr<Controller> made = make_controller(m.robot, genotype, m.neural, m.sim.sample_step, offsets);
    Controller& controller = *made;
    o.synapses = controller.connections();
    const bool penalised = m.neural.penalty != nn::OscillationPenalty::None;
    controller.set_recording(record_control || penalised);
    o.result = sim::evaluate(m.robot, controller, m.sim, options);
    o.failed = o.result.failed;
    o.failure = o.result.failure;
    o.distance_fitness = o.result.fitness;
    o.fitness = o.result.fitness;
    if (!o.failed && penalised) {
        const auto& rec = controller.record();
        o.fitness = penalised_fitness(o.fitness, m.neural, rec.commands, rec.joints, m.sim.sample_step);
    }
    if (!std::isfinite(o.fitness)) {   // never let a NaN reach selection or a file
        o.failed = true;
        o.failure = "non-finite fitness";
        o.fitness = m.sim.failure_fitness;
    }
    if (record_control) o.control = controller.record();
    return o;
}

gp::DirectGenes direct_offset_genes(const Model& m) {
    gp::DirectGenes g;
    if (!m.neural.direct_offsets) return g;
    g.count = m.robot.actuated().size();
    g.limit = kOffsetLimit;
    g.sigma = m.neural.offset_sigma;
    g.rate = m.neural.offset_rate;
    return g;
}

void check_offsets(const Model& m, std::span<const double> offsets, const std::string& who, const std::string& file) {
    const gp::DirectGenes genes = direct_offset_genes(m);
    if (genes.count == 0) {
        if (!offsets.empty())
            throw InputError(who + ": offsets are Offset-HybrID's direct genes beside HyperGP trees; these settings "
                                   "have none (Neural.directOffsets = 0)",
                             file);
        return;
    }
    if (offsets.size() != genes.count)
        throw InputError(fmt::format("{}: {} offsets, but these settings' Offset-HybrID (Neural.directOffsets) has "
                                     "one per hinge of robot {}: {}",
                                     who, offsets.size(), m.robot.name, genes.count),
                         file);
    for (std::size_t i = 0; i < offsets.size(); ++i)
        if (!std::isfinite(offsets[i]) || std::abs(offsets[i]) > genes.limit)
            throw InputError(fmt::format("{}: offset {} is {}, outside [-{}, {}] (units of pi/2)", who, i, offsets[i],
                                         genes.limit, genes.limit),
                             file);
}

std::string job_body(const tree::Forest& genotype, sim::Descriptor descriptor, std::span<const double> offsets,
                     std::size_t robot_body) {
    std::string body;
    for (const auto& t : genotype) body += t.to_string() + "\n";
    if (!offsets.empty()) body += fmt::format("offsets {}\n", fmt::join(offsets, " "));
    if (robot_body > 0) body += fmt::format("body {}\n", robot_body);
    if (descriptor != sim::Descriptor::None) body += "descriptor " + sim::to_string(descriptor) + "\n";
    return body;
}

Job parse_job_body(const std::string& body) {
    Job job;
    std::istringstream in(body);
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        if (line.starts_with("offsets ")) {   // after the trees, before a descriptor
            if (job.genotype.empty()) throw std::invalid_argument("hypergp job: offsets before the trees");
            if (!job.offsets.empty()) throw std::invalid_argument("hypergp job: two lines of offsets");
            if (job.body > 0) throw std::invalid_argument("hypergp job: offsets after the body");
            std::istringstream items(line.substr(8));
            std::string item;
            while (items >> item) {
                double d = 0;
                const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), d);
                if (ec != std::errc() || end != item.data() + item.size() || !std::isfinite(d))
                    throw std::invalid_argument("hypergp job: bad offset '" + item + "'");
                job.offsets.push_back(d);
            }
            if (job.offsets.empty()) throw std::invalid_argument("hypergp job: an empty line of offsets");
            continue;
        }
        if (line.starts_with("body ")) {   // after the trees and offsets, before a descriptor
            if (job.genotype.empty()) throw std::invalid_argument("hypergp job: a body before the trees");
            if (job.body > 0) throw std::invalid_argument("hypergp job: two lines of body");
            const std::string item = line.substr(5);
            const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), job.body);
            if (ec != std::errc() || end != item.data() + item.size() || job.body == 0)
                throw std::invalid_argument("hypergp job: bad body '" + item + "' (a number >= 1)");
            continue;
        }
        if ((!job.offsets.empty() || job.body > 0) && !line.starts_with("descriptor "))
            throw std::invalid_argument("hypergp job: a tree after the offsets or the body");
        if (line.starts_with("descriptor ")) {   // the last line, when present
            if (job.genotype.empty()) throw std::invalid_argument("hypergp job: a descriptor before the trees");
            job.descriptor = sim::descriptor_from(line.substr(11));
            if (std::getline(in, line) && !line.empty())
                throw std::invalid_argument("hypergp job: a line after the descriptor");
            break;
        }
        job.genotype.push_back(tree::Tree::parse(line));
    }
    if (job.genotype.empty()) throw std::invalid_argument("hypergp job has no trees");
    return job;
}

sim::EvalReply to_reply(const Model& m, const Outcome& o, std::vector<double> descriptor) {
    sim::EvalReply reply{o.fitness, o.failed ? std::vector<double>{} : std::move(descriptor), o.failed, o.failure};
    if (!o.failed) std::tie(reply.distance, reply.elevation) = sim::walk_terms(m.robot, o.result);
    return reply;
}

sim::EvalOptions options_for(const WalkNeeds& needs, sim::Descriptor descriptor) {
    sim::EvalOptions options;
    options.record_trace = needs.trace;
    options.record_ground = needs.contacts || sim::needs_ground(descriptor);
    return options;
}

void apply_score(Outcome& o, const Score& score, const Model& m, const io::Settings& s) {
    if (!score || o.failed) return;
    o.fitness = score(m, s, o);
    if (!std::isfinite(o.fitness)) {
        o.failed = true;
        o.failure = "non-finite fitness";
        o.fitness = m.sim.failure_fitness;
    }
}

std::function<std::string(const std::string&)> make_job_handler(std::function<io::Settings()> settings,
                                                                 Score score, WalkNeeds needs) {
    struct Loaded {
        io::Settings settings;
        std::vector<Model> bodies;   // by growing body; one when the robot does not grow
    };
    auto loaded = std::make_shared<std::optional<Loaded>>();
    return [loaded, settings = std::move(settings), score = std::move(score), needs](const std::string& body) {
        if (!*loaded) {
            io::Settings s = settings();
            const Model m = Model::from_settings(s);
            std::vector<Model> bodies;
            for (std::size_t k = 0; k <= m.grow_robots.size(); ++k) bodies.push_back(m.on_body(k));
            loaded->emplace(Loaded{std::move(s), std::move(bodies)});
        }
        const Job job = parse_job_body(body);
        if (job.body >= (*loaded)->bodies.size())
            throw std::invalid_argument(fmt::format("hypergp job: body {}, but the settings' robot has {}", job.body,
                                                    (*loaded)->bodies.size()));
        const Model& m = (*loaded)->bodies[job.body];
        const Outcome o = evaluate_job(m, (*loaded)->settings, job, score, needs);
        return sim::format_eval_reply(
            to_reply(m, o, o.failed ? std::vector<double>{} : sim::descriptor_of(job.descriptor, m.robot, o.result)));
    };
}

} // namespace cic::hypergp
