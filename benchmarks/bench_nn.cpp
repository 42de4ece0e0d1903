// Cost of the neural part of one HyperGP evaluation against the physics:
// substrate build (hypercube encoding), network steps and the controller, for
// the thesis robot R1 with 6 legs and a 30-node CPPF; a 15 s evaluation at
// 0.0125 s is 1200 control steps. The physics-only and full evaluations run in
// the same program so their ratio is measured within one run.
//   cic_bench_nn --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "cic/nn/substrate.hpp"
#include "cic/sim/evaluate.hpp"
#include "cic/sim/robot.hpp"
#include "cic/experiments/hypergp/neural_controller.hpp"
#include "cic/experiments/hypergp/substrate_geometry.hpp"

namespace {

constexpr int kSteps = 1200;   // 15 s / 0.0125 s

// 30 nodes over the thesis's functions add mul atan sin gauss, x0..x3 and +-1.
const char* kTree =
    "(add (sin (mul (gauss (add x0 x1)) (add x2 -1))) (atan (add (gauss (mul x1 (sin (mul x3 1))))"
    " (mul (sin (add x0 x3)) (gauss (add x2 (mul x1 -1)))))))";

struct Fixture {
    cic::sim::RobotSpec robot = cic::sim::preset(1, true);
    cic::nn::NeuralConfig cfg;
    cic::nn::NeuronLayout layout;
    cic::tree::Forest genotype{cic::tree::Tree::parse(kTree)};
    explicit Fixture(double threshold) {
        cfg.threshold = threshold;
        layout = cic::nn::make_neuron_layout(cic::hypergp::substrate_geometry(robot), cfg);
    }
};

// Threshold in 1/100 from the benchmark argument: 20 = the thesis's 0.2, 0 = every pair.
double threshold_of(const benchmark::State& s) { return static_cast<double>(s.range(0)) / 100.0; }

void BM_SubstrateBuild(benchmark::State& state) {
    Fixture f(threshold_of(state));
    std::size_t synapses = 0;
    for (auto _ : state) {
        auto net = cic::nn::build_network(f.layout, f.genotype, f.cfg);
        synapses = net.synapse_count();
        benchmark::DoNotOptimize(synapses);
    }
    state.counters["tree_nodes"] = static_cast<double>(f.genotype[0].size());
    state.counters["synapses"] = static_cast<double>(synapses);
    state.counters["neurons"] = static_cast<double>(f.layout.input.size() + f.layout.hidden.size() + f.layout.output.size());
}
BENCHMARK(BM_SubstrateBuild)->Arg(20)->Arg(0)->Unit(benchmark::kMicrosecond);

// One evaluation's worth of network steps (reset + 1200 steps).
void BM_NetworkEvaluation(benchmark::State& state) {
    Fixture f(threshold_of(state));
    auto net = cic::nn::build_network(f.layout, f.genotype, f.cfg);
    std::vector<double> in(net.input_count()), out(net.output_count());
    for (auto _ : state) {
        net.reset();
        for (int s = 0; s < kSteps; ++s) {
            for (std::size_t j = 0; j < in.size(); ++j) in[j] = out[j % out.size()] * 0.9;
            net.step(in, out);
        }
        benchmark::DoNotOptimize(out.data());
    }
    state.counters["synapses"] = static_cast<double>(net.synapse_count());
    state.counters["ns_per_step"] = benchmark::Counter(static_cast<double>(kSteps),
                                                       benchmark::Counter::kIsIterationInvariantRate |
                                                           benchmark::Counter::kInvert);
}
BENCHMARK(BM_NetworkEvaluation)->Arg(20)->Arg(0)->Unit(benchmark::kMicrosecond);

// The controller as the simulator sees it: substrate build + reset + 1200 steps.
void BM_ControllerEvaluation(benchmark::State& state) {
    Fixture f(threshold_of(state));
    const std::size_t joints = f.layout.joint_count;
    std::vector<double> angles(joints, 0.0), desired(joints);
    for (auto _ : state) {
        auto c = cic::hypergp::make_neural_controller(f.robot, f.genotype, f.cfg);
        c.reset(joints);
        for (int s = 0; s < kSteps; ++s) {
            c.step(0.0125 * s, angles, desired);
            for (std::size_t j = 0; j < joints; ++j) angles[j] = 0.5 * desired[j];
        }
        benchmark::DoNotOptimize(desired.data());
    }
}
BENCHMARK(BM_ControllerEvaluation)->Arg(20)->Arg(0)->Unit(benchmark::kMicrosecond);

// Physics alone: the same robot and 15 s under a sine tripod-like gait.
void BM_PhysicsEvaluationSine(benchmark::State& state) {
    const auto robot = cic::sim::preset(1, true);
    cic::sim::SimConfig sim;
    for (auto _ : state) {
        cic::sim::SineController gait({{0.5, 0.5, 0.0}, {0.5, 0.5, 3.14159}});
        auto r = cic::sim::evaluate(robot, gait, sim);
        benchmark::DoNotOptimize(r.fitness);
    }
}
BENCHMARK(BM_PhysicsEvaluationSine)->Unit(benchmark::kMillisecond);

// A whole evaluation with the neural controller: substrate + network + physics.
void BM_FullEvaluationNeural(benchmark::State& state) {
    Fixture f(threshold_of(state));
    cic::sim::SimConfig sim;
    for (auto _ : state) {
        auto c = cic::hypergp::make_neural_controller(f.robot, f.genotype, f.cfg);
        auto r = cic::sim::evaluate(f.robot, c, sim);
        benchmark::DoNotOptimize(r.fitness);
    }
}
BENCHMARK(BM_FullEvaluationNeural)->Arg(20)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
