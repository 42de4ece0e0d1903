// One evaluation's cost against the robot's size (issue 38): centipedes of 15
// to 511 modules (sim/centipede.hpp), 15 s of the thesis's simulation, under
// each Simulator.collisionSpace. The goal is cost linear in modules. Run
// through scripts/bench.sh, which prints the time per module and its growth.
#include <benchmark/benchmark.h>

#include <cmath>

#include "cic/sim/centipede.hpp"
#include "cic/sim/controller.hpp"
#include "cic/sim/evaluate.hpp"

using namespace cic::sim;

namespace {

// A travelling wave along the joints: every leg moves, feet touch the ground
// and, now and then, each other.
GaitSpec wave(std::size_t joints) {
    GaitSpec g;
    g.frequency = 0.6;
    for (std::size_t j = 0; j < joints; ++j) g.joints.push_back({0.6, 0.7 * static_cast<double>(j), 0.0, 0.0, 0.0});
    return g;
}

// Args: pairs P (8P - 1 modules), collision space (0 simple, 1 sweep, 2 sap).
void BM_CentipedeEvaluation(benchmark::State& state) {
    const RobotSpec robot = centipede(static_cast<int>(state.range(0)), false);
    SimConfig cfg;   // the thesis's 15 s at 0.0125 s, self-collision on
    cfg.collision_space = static_cast<int>(state.range(1));
    for (auto _ : state) {
        GaitController c(wave(robot.actuated().size()));
        const EvalResult r = evaluate(robot, c, cfg);
        if (r.failed) state.SkipWithError(r.failure.c_str());
        benchmark::DoNotOptimize(r.fitness);
    }
    state.counters["modules"] = static_cast<double>(robot.modules.size());
}
BENCHMARK(BM_CentipedeEvaluation)
    ->ArgsProduct({{2, 4, 8, 16, 32, 64}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);

} // namespace

BENCHMARK_MAIN();
