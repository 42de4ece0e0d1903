// Genotype -> the controller Neural.substrate names (see controller.hpp).
#include "cic/experiments/hypergp/controller.hpp"

#include <numbers>
#include <stdexcept>

#include "cic/sim/cpg.hpp"
#include "cic/experiments/hypergp/cpg_substrate.hpp"
#include "cic/experiments/hypergp/gait_substrate.hpp"
#include "cic/experiments/hypergp/neural_controller.hpp"
#include "cic/io/substrate_names.hpp"

namespace cic::hypergp {

RecordedController::RecordedController(std::unique_ptr<sim::Controller> inner, double scale, std::size_t connections)
    : inner_(std::move(inner)), scale_(scale), connections_(connections) {
    if (!inner_) throw std::invalid_argument("RecordedController: no controller");
    if (!(scale_ > 0)) throw std::invalid_argument("RecordedController: the scale must be > 0");
}

void RecordedController::reset(std::size_t joints) {
    inner_->reset(joints);
    record_ = ControlRecord{};
    record_.joints = joints;
}

void RecordedController::step(double t, std::span<const double> angles, std::span<double> desired) {
    inner_->step(t, angles, desired);
    if (!recording_) return;
    record_.times.push_back(t);
    for (double d : desired) record_.outputs.push_back(d / scale_);
    record_.commands.insert(record_.commands.end(), desired.begin(), desired.end());
}

namespace {

std::vector<ControllerKind>& kinds() {
    static std::vector<ControllerKind> k;
    return k;
}

constexpr double kHalfPi = std::numbers::pi / 2;

// The built-in substrates (docs/hypergp.md).
const ControllerRegistrar network{{"network", "the thesis's recurrent network",
    [](const sim::RobotSpec& robot, const tree::Forest& genotype, const nn::NeuralConfig& cfg, double) {
        return std::unique_ptr<Controller>(
            std::make_unique<NeuralController>(make_neural_controller(robot, genotype, cfg)));
    }}};

const ControllerRegistrar cpg{{"cpg", "coupled oscillators, one per joint",
    [](const sim::RobotSpec& robot, const tree::Forest& genotype, const nn::NeuralConfig& cfg, double step) {
        sim::CpgSpec spec = cpg_spec(robot, genotype, cfg, step);
        const std::size_t pairs = spec.edges.size();
        const double range = spec.range;
        return std::unique_ptr<Controller>(
            std::make_unique<RecordedController>(std::make_unique<sim::CpgController>(std::move(spec)), range, pairs));
    }}};

std::unique_ptr<Controller> make_gait(const sim::RobotSpec& robot, const tree::Forest& genotype,
                                      std::span<const double> offsets, const nn::NeuralConfig& cfg) {
    sim::GaitSpec spec = gait_spec(robot, genotype, cfg, offsets);
    const std::size_t joints = spec.joints.size();
    return std::make_unique<RecordedController>(std::make_unique<sim::GaitController>(std::move(spec)), kHalfPi,
                                                joints);
}

const ControllerRegistrar gait{{"gait", "each joint's amplitude, phase and offset, one evolved frequency",
    [](const sim::RobotSpec& robot, const tree::Forest& genotype, const nn::NeuralConfig& cfg, double) {
        return make_gait(robot, genotype, {}, cfg);
    },
    [](const sim::RobotSpec& robot, const tree::Forest& genotype, std::span<const double> offsets,
       const nn::NeuralConfig& cfg, double) { return make_gait(robot, genotype, offsets, cfg); }}};

} // namespace

void register_controller(ControllerKind kind) {
    if (!kind.make) throw std::invalid_argument("controller '" + kind.name + "' has no factory");
    if (find_controller(kind.name)) throw std::invalid_argument("controller '" + kind.name + "' is registered twice");
    // The settings know the built-ins' names already; a new one joins the key's choices.
    if (!io::is_substrate_name(kind.name)) io::register_substrate_name({kind.name, kind.doc});
    kinds().push_back(std::move(kind));
}

const ControllerKind* find_controller(std::string_view name) {
    for (const auto& k : kinds())
        if (k.name == name) return &k;
    return nullptr;
}

bool takes_direct_offsets(std::string_view name) {
    const ControllerKind* kind = find_controller(name);
    return kind && kind->make_with_offsets;
}

std::unique_ptr<Controller> make_controller(const sim::RobotSpec& robot, const tree::Forest& genotype,
                                            const nn::NeuralConfig& cfg, double control_step,
                                            std::span<const double> offsets) {
    const ControllerKind* kind = find_controller(cfg.substrate);
    if (!kind) throw std::invalid_argument("make_controller: no controller is registered as '" + cfg.substrate + "'");
    if (offsets.empty()) return kind->make(robot, genotype, cfg, control_step);
    if (!kind->make_with_offsets)
        throw std::invalid_argument("make_controller: substrate '" + cfg.substrate + "' takes no direct offsets");
    return kind->make_with_offsets(robot, genotype, offsets, cfg, control_step);
}

} // namespace cic::hypergp
