// Whole symbolic-regression runs in-process at the settings of DEAP's symbreg
// example (settings/symreg_deap.xml: Koza-1, population 300, 41 evaluated
// generations, one worker). Reports runs/s and CPU seconds per run, i.e. the
// engine's own cost without process start-up or the run folder that
// scripts/compare-deap.sh also counts.
//
//   cic_bench_symreg_run [--benchmark_repetitions=3]
#include <benchmark/benchmark.h>

#include <cstdint>
#include <filesystem>

#include "cic/gp/evolution.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/experiments/experiment.hpp"

namespace {

using namespace cic;

const io::Settings& deap_settings() {
    static const io::Settings s =
        io::load_settings(std::filesystem::path(CIC_SOURCE_DIR) / "settings" / "symreg_deap.xml", {});
    return s;
}

// One run with `seed`; returns whether its best individual solved the task
// (every point a hit, as summary.txt's "(success)").
bool one_run(const io::Settings& s, std::uint64_t seed, experiments::Experiment& experiment) {
    const tree::PrimitiveSet ps(s.gp.primitives);
    gp::EvolutionState state;
    state.seed = seed;
    state.rng = Rng(seed);
    const gp::StopConditions stop{s.control.maximum_iterations, s.control.minimum_fitness};
    const auto result = gp::evolve(s.gp, s.bloat, stop, ps, experiment.evaluator(), state, std::nullopt, {});
    return experiment.success(result.population.best());
}

// Seeds 1..kRuns, one per iteration (a fixed set, so runs compare across
// builds); the CPU column is the CPU time per run.
constexpr int kRuns = 40;

void BM_SymregDeapRun(benchmark::State& bstate) {
    const io::Settings& s = deap_settings();
    const auto dir = std::filesystem::path(CIC_SOURCE_DIR) / "settings";
    experiments::Context ctx{s, dir, dir / "symreg_deap.xml", "", 1};
    auto experiment = experiments::make_experiment(ctx);
    std::uint64_t seed = 1;
    double successes = 0, runs = 0;
    for (auto _ : bstate) {
        successes += one_run(s, seed++, *experiment) ? 1 : 0;
        runs += 1;
    }
    bstate.counters["runs/s"] = benchmark::Counter(runs, benchmark::Counter::kIsRate);   // per CPU second
    bstate.counters["success%"] = benchmark::Counter(runs > 0 ? 100.0 * successes / runs : 0.0);
}

} // namespace

BENCHMARK(BM_SymregDeapRun)->Iterations(kRuns)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
