#include "experiments/hypergp/model.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "cic/io/robot_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "experiments/hypergp/oscillation.hpp"

namespace cic::hypergp {

Model Model::from_settings(const io::Settings& s) {
    Model m;
    m.robot = s.robot.robot_file.empty() ? sim::preset(s.robot.robot_type, s.neural.middle_legs)
                                         : io::read_robot_file(s.robot.robot_file);
    m.robot.validate();
    m.sim = s.sim;
    m.neural = s.neural;
    return m;
}

Outcome run(const Model& m, const tree::Forest& genotype, const sim::EvalOptions& options, bool record_control) {
    Outcome o;
    NeuralController controller = make_neural_controller(m.robot, genotype, m.neural);
    o.synapses = controller.network().synapse_count();
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

std::string job_body(const tree::Forest& genotype) {
    std::string body;
    for (const auto& t : genotype) body += t.to_string() + "\n";
    return body;
}

tree::Forest parse_job_body(const std::string& body) {
    tree::Forest f;
    std::istringstream in(body);
    std::string line;
    while (std::getline(in, line))
        if (!line.empty()) f.push_back(tree::Tree::parse(line));
    if (f.empty()) throw std::invalid_argument("hypergp job has no trees");
    return f;
}

std::string reply(const Outcome& o) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a %d", o.fitness, o.failed ? 1 : 0);
    return buf;
}

Reply parse_reply(const std::string& text) {
    Reply r;
    int failed = 0;
    if (std::sscanf(text.c_str(), "%la %d", &r.fitness, &failed) != 2)
        throw std::runtime_error("malformed hypergp worker reply '" + text + "'");
    r.failed = failed != 0;
    return r;
}

std::function<std::string(const std::string&)> make_job_handler(const std::string& settings_file) {
    auto model = std::make_shared<std::optional<Model>>();
    return [model, settings_file](const std::string& body) {
        if (!*model) {
            if (settings_file.empty()) throw std::invalid_argument("hypergp jobs need `cic worker --settings FILE`");
            *model = Model::from_settings(io::read_settings(settings_file));
        }
        return reply(run(**model, parse_job_body(body)));
    };
}

} // namespace cic::hypergp
