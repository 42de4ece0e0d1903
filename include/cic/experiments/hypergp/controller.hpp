#pragma once
// What a HyperGP genotype becomes (Neural.substrate, docs/hypergp.md): the
// thesis's recurrent network, a CPG of coupled oscillators, or an open-loop
// gait. Every one records what it commanded, for the oscillation penalty,
// traces and replays, and counts its connections for summaries.
#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cic/nn/config.hpp"
#include "cic/sim/controller.hpp"
#include "cic/sim/robot.hpp"
#include "cic/tree/tree.hpp"

namespace cic::hypergp {

// What the controller did, step-major: value of joint j at step s is [s * joints + j].
struct ControlRecord {
    std::size_t joints = 0;
    std::vector<double> times;      // t of each step
    std::vector<double> outputs;    // raw outputs in [-1, 1]: network outputs, CPG states x_i, gait / (pi/2)
    std::vector<double> commands;   // desired angles sent to the simulator, rad
    std::size_t steps() const { return times.size(); }
};

class Controller : public sim::Controller {
public:
    // Recording is off by default (it allocates); reset() clears the record.
    virtual void set_recording(bool on) = 0;
    virtual const ControlRecord& record() const = 0;
    // Synapses of the network, coupled pairs of the CPG, joints of a gait.
    virtual std::size_t connections() const = 0;
};

// The controller the genotype describes for this robot: the one registered
// under cfg.substrate. `control_step` is the simulator's sample step (the CPG
// integrates over it). Throws like the substrate it builds (cic::InputError
// for a bad config, std::invalid_argument for a genotype that does not fit or
// a substrate nothing registered).
// `offsets` are the genotype's direct offsets (Neural.directOffsets), empty
// without them; a substrate that takes none refuses them (std::invalid_argument).
std::unique_ptr<Controller> make_controller(const sim::RobotSpec& robot, const tree::Forest& genotype,
                                            const nn::NeuralConfig& cfg, double control_step,
                                            std::span<const double> offsets = {});

// The open registry of controllers (docs/extending.md). A controller is one
// file with a static ControllerRegistrar: its Neural.substrate name and how a
// genotype builds it. Runs, worker processes, `view`, `trace`, `assess` and
// `render` all build controllers through make_controller, so a registered one
// is replayed as it was evaluated. The built-ins (network, cpg, gait) register
// in controller.cpp.
using ControllerFactory = std::function<std::unique_ptr<Controller>(
    const sim::RobotSpec& robot, const tree::Forest& genotype, const nn::NeuralConfig& cfg, double control_step)>;

// A substrate that also reads direct per-joint offsets (Offset-HybrID).
using OffsetControllerFactory = std::function<std::unique_ptr<Controller>(
    const sim::RobotSpec& robot, const tree::Forest& genotype, std::span<const double> offsets,
    const nn::NeuralConfig& cfg, double control_step)>;

struct ControllerKind {
    std::string name;   // the Neural.substrate value
    std::string doc;    // one line, for the key's documentation
    ControllerFactory make;
    OffsetControllerFactory make_with_offsets = {};   // empty: takes no direct offsets
};

// Whether the substrate called `name` takes direct offsets (Neural.directOffsets).
bool takes_direct_offsets(std::string_view name);

// Throws std::invalid_argument for a name registered twice or a kind without `make`.
void register_controller(ControllerKind kind);
// nullptr when nothing registered this name.
const ControllerKind* find_controller(std::string_view name);

struct ControllerRegistrar {
    explicit ControllerRegistrar(ControllerKind kind) { register_controller(std::move(kind)); }
};

// A sim controller with a record of its commands: outputs = command / scale.
// For the controllers whose commands are their outputs times a range.
class RecordedController final : public Controller {
public:
    RecordedController(std::unique_ptr<sim::Controller> inner, double scale, std::size_t connections);
    void reset(std::size_t joints) override;
    void step(double t, std::span<const double> angles, std::span<double> desired) override;
    void set_recording(bool on) override { recording_ = on; }
    const ControlRecord& record() const override { return record_; }
    std::size_t connections() const override { return connections_; }
    const sim::Controller& inner() const { return *inner_; }

private:
    std::unique_ptr<sim::Controller> inner_;
    double scale_;
    std::size_t connections_;
    bool recording_ = false;
    ControlRecord record_;
};

} // namespace cic::hypergp
