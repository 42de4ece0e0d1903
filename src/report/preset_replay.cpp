#include "cic/report/preset_replay.hpp"

#include <fmt/format.h>

#include <charconv>
#include <filesystem>
#include <memory>
#include <cmath>
#include <numbers>

#include "cic/core/error.hpp"
#include "cic/io/robot_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/sim/evaluate.hpp"
#include "cic/sim/layout.hpp"
#include "cic/sim/robot.hpp"

namespace cic::report {
namespace {

namespace fs = std::filesystem;

std::vector<double> parse_numbers(std::string_view text, std::string_view spec) {
    std::vector<double> out;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = text.find(',', start);
        const std::string_view cell = text.substr(start, comma == std::string_view::npos ? comma : comma - start);
        double v = 0;
        const auto res = std::from_chars(cell.data(), cell.data() + cell.size(), v);
        if (cell.empty() || res.ec != std::errc() || res.ptr != cell.data() + cell.size() || !std::isfinite(v))
            throw InputError(fmt::format("controller '{}': '{}' is not a number", spec, cell));
        out.push_back(v);
        if (comma == std::string_view::npos) return out;
        start = comma + 1;
    }
}

// Wraps a controller and keeps what it returned each step: the "raw outputs"
// of a hand-written controller, before the simulator clamps them.
class OutputRecorder final : public sim::Controller {
public:
    explicit OutputRecorder(sim::Controller& inner) : inner_(inner) {}
    void reset(std::size_t joints) override {
        outputs.clear();
        inner_.reset(joints);
    }
    void step(double t, std::span<const double> angles, std::span<double> desired) override {
        inner_.step(t, angles, desired);
        outputs.emplace_back(desired.begin(), desired.end());
    }
    std::vector<std::vector<double>> outputs;

private:
    sim::Controller& inner_;
};

} // namespace

std::unique_ptr<sim::Controller> parse_controller_spec(std::string_view spec) {
    // The bare words are shorthands every command takes alike (simulate, view, trace, render).
    if (spec == "sine") return parse_controller_spec("sine:0.8,0.5");
    if (spec == "constant") return parse_controller_spec("constant:0");
    const std::size_t colon = spec.find(':');
    const std::string_view kind = spec.substr(0, colon);
    const std::string_view args = colon == std::string_view::npos ? std::string_view() : spec.substr(colon + 1);
    if (kind == "sine") {
        if (args.empty()) throw InputError(fmt::format("controller '{}': expected sine:AMPLITUDE,FREQUENCY[,PHASE_STEP]", spec));
        const auto v = parse_numbers(args, spec);
        if (v.size() < 2 || v.size() > 3)
            throw InputError(fmt::format("controller '{}': expected sine:AMPLITUDE,FREQUENCY[,PHASE_STEP]", spec));
        if (v[0] < 0 || v[1] <= 0)
            throw InputError(fmt::format("controller '{}': amplitude must be >= 0 and frequency > 0", spec));
        const double step = v.size() == 3 ? v[2] : std::numbers::pi / 2;
        // 64 joints cover any robot of a sane size; SineController reuses the last entry beyond.
        std::vector<sim::SineJoint> joints;
        for (int j = 0; j < 64; ++j) joints.push_back({v[0], v[1], j * step});
        return std::make_unique<sim::SineController>(std::move(joints));
    }
    if (kind == "constant") {
        const auto v = parse_numbers(args, spec);
        if (v.size() != 1) throw InputError(fmt::format("controller '{}': expected constant:ANGLE", spec));
        return std::make_unique<sim::ConstantController>(v[0]);
    }
    throw InputError(fmt::format("unknown controller '{}' (expected sine, sine:A,F[,P], constant or constant:ANGLE)", spec));
}

int parse_robot_name(std::string_view name) {
    for (int k = 0; k <= 2; ++k)
        if (name == fmt::format("R{}", k) || name == fmt::format("r{}", k) || name == fmt::format("{}", k)) return k;
    throw InputError(fmt::format("unknown robot '{}' (expected R0, R1, R2 or an existing robot file)", name));
}

ReplayItem replay_preset(const PresetReplay& preset, double fps, bool trace) {
    const sim::RobotSpec robot = preset.robot_file.empty() ? sim::preset(preset.robot_type, preset.middle_legs)
                                                           : io::read_robot_file(preset.robot_file);
    auto controller = parse_controller_spec(preset.controller);
    OutputRecorder recorder(*controller);
    sim::EvalOptions options;
    options.record_fps = fps;
    options.record_trace = trace;
    options.record_ground = trace;
    sim::EvalResult result = sim::evaluate(robot, recorder, preset.sim, options);
    if (result.failed) throw std::runtime_error("simulation failed: " + result.failure);

    ReplayItem item;
    item.label = fmt::format("{} {}", robot.name, preset.controller);
    item.stored_fitness = item.replayed_fitness = result.fitness;
    item.generation = -1;
    if (result.recording) item.recording = std::move(*result.recording);
    item.trace = std::move(result.trace);
    if (trace) item.raw_outputs = std::move(recorder.outputs);
    const sim::BodyLayout layout = sim::make_body_layout(robot);
    item.centre_body = layout.geoms.at(static_cast<std::size_t>(layout.centre_geom)).body;
    for (int m : robot.actuated()) {
        const std::string& name = robot.modules[static_cast<std::size_t>(m)].name;
        item.joint_names.push_back(name.empty() ? fmt::format("m{}", m) : name);
    }
    item.raw_fitness = result.fitness;
    fill_walk(item, robot, result);
    return item;
}

std::vector<std::string> joint_names_of(const ReplayItem& item) {
    if (!item.joint_names.empty()) return item.joint_names;
    std::size_t n = item.trace.empty() ? 0 : item.trace.front().desired.size();
    std::vector<std::string> out;
    for (std::size_t j = 0; j < n; ++j) out.push_back(fmt::format("j{}", j));
    return out;
}

std::vector<ReplayItem> load_replay(const ReplaySource& source, int count, double fps, bool trace) {
    if (source.input.empty() == source.robot.empty())
        throw InputError("give either a RUN_DIR / POPULATION.xml or --robot R0|R1|R2 (with --controller)");
    if (!source.cell.empty() && source.individual != "best")
        throw InputError("give --individual or --cell, not both");
    if (!source.input.empty())
        return replay(source.input, source.cell.empty() ? source.individual : "cell:" + source.cell, count, fps, trace);
    if (source.seconds < 0) throw InputError("--seconds must be positive");
    PresetReplay preset;
    if (fs::exists(source.robot))
        preset.robot_file = source.robot;
    else
        preset.robot_type = parse_robot_name(source.robot);
    preset.middle_legs = source.middle_legs;
    preset.controller = source.controller;
    for (const auto& o : source.overrides)
        if (o.rfind("Simulator.", 0) != 0)
            throw InputError(fmt::format("--set {}: a replay takes only Simulator keys", o));
    preset.sim = io::load_settings({}, source.overrides).sim;
    if (source.seconds > 0) preset.sim.sample_to = preset.sim.sample_from + source.seconds;
    if (preset.sim.delayed_start > preset.sim.sample_to) preset.sim.delayed_start = preset.sim.sample_from;
    return {replay_preset(preset, fps, trace)};
}

} // namespace cic::report
