// The registry of experiment types (registry.hpp).
#include "cic/experiments/registry.hpp"
#include "cic/experiments/hypergp/experiment.hpp"

#include <stdexcept>

#include "cic/io/settings_extension.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/sim/job_text.hpp"

namespace cic::experiments {
namespace {

std::vector<ExperimentKind>& kinds() {
    static std::vector<ExperimentKind> k;
    return k;
}

} // namespace

io::Settings WorkerContext::load_settings() const {
    if (!settings_text.empty()) return io::read_settings_string(settings_text, "settings from rank 0");
    if (settings_file.empty()) throw std::invalid_argument("these jobs need `cic worker --settings FILE`");
    return io::read_settings(settings_file);
}

void register_experiment(ExperimentKind kind) {
    const std::string name = kind.type.name;
    if (kind.score && kind.type.family == io::ExperimentFamily::HyperGP) {
        // A score is all a type needs: HyperGP's experiment, its jobs scored with it.
        if (!kind.make) kind.make = [name](const Context& ctx) { return make_hypergp_experiment(ctx, name); };
        if (kind.job_kinds.empty())
            kind.job_kinds[name] = [score = kind.score, needs = kind.needs](const WorkerContext& w) {
                return hypergp::make_job_handler([w] { return w.load_settings(); }, score, needs);
            };
    } else if (kind.score) {
        throw std::invalid_argument("experiment type '" + name + "': a score of its own is for HyperGP-family types");
    }
    for (const auto& k : kinds()) {
        if (k.type.name == name) throw std::invalid_argument("experiment type '" + name + "' is registered twice");
        for (const auto& [job, _] : kind.job_kinds)
            if (k.job_kinds.count(job))
                throw std::invalid_argument("experiment type '" + name + "': job kind '" + job +
                                            "' is already served by '" + k.type.name + "'");
    }
    if (kind.job_kinds.count("sine"))
        throw std::invalid_argument("experiment type '" + name + "': job kind 'sine' is the simulator's own");
    if (kind.type.family != io::ExperimentFamily::Gait && !kind.make)
        throw std::invalid_argument("experiment type '" + name + "' of family " +
                                    std::string(io::to_string(kind.type.family)) + " needs `make`");
    if (const io::ExperimentType* known = io::find_experiment_type(name)) {
        // A built-in type: the settings know it already; its behaviour registers here.
        if (known->family != kind.type.family || known->section != kind.type.section || !kind.keys.empty())
            throw std::invalid_argument("experiment type '" + name + "' is a built-in one of another shape");
    } else {
        io::register_settings_keys(kind.keys);
        io::register_experiment_type(kind.type);
    }
    kinds().push_back(std::move(kind));
}

const std::vector<ExperimentKind>& experiment_kinds() { return kinds(); }

const ExperimentKind& experiment_kind(std::string_view name) {
    for (const auto& k : kinds())
        if (k.type.name == name) return k;
    throw std::logic_error("experiment type '" + std::string(name) +
                           "' has no registered behaviour (is its library linked whole?)");
}

hypergp::Outcome evaluate_as_type(const hypergp::Model& model, const io::Settings& settings,
                                  const tree::Forest& genotype, sim::EvalOptions options, bool record_control) {
    const ExperimentKind& kind = experiment_kind(settings.experiment.type);
    options.record_trace = options.record_trace || kind.needs.trace;
    options.record_ground = options.record_ground || kind.needs.contacts;
    hypergp::Outcome o = hypergp::run(model, genotype, options, record_control);
    hypergp::apply_score(o, kind.score, model, settings);
    return o;
}

std::map<std::string, JobHandler> make_job_handlers(const WorkerContext& context) {
    std::map<std::string, JobHandler> handlers;
    handlers["sine"] = &sim::run_sine_job;   // robot + SimConfig + sine joints -> fitness reply
    for (const auto& k : kinds())
        for (const auto& [job, factory] : k.job_kinds) handlers[job] = factory(context);
    return handlers;
}

} // namespace cic::experiments
