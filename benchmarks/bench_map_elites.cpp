// What a MAP-Elites run spends outside physics, per evaluation: making a
// solution (Gaussian mutation of a gait vector, a CMA-ME generation, or GP
// crossover and mutation of a 3-tree genotype) and offering it to a 625-cell
// duty-factor archive, and
// writing the archive's checkpoint; against one physics evaluation of R1 with
// the ground recorded for the duty factors (scripts/bench.sh prints the ratio).
#include <benchmark/benchmark.h>

#include "cic/experiments/gait/cma_me_emitter.hpp"
#include "cic/gp/forest_map_elites.hpp"
#include "cic/gp/vector_map_elites.hpp"
#include "cic/io/archive_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/sim/controller.hpp"
#include "cic/sim/evaluate.hpp"
#include "cic/sim/robot.hpp"

namespace {

using cic::gp::Evaluation;

const cic::gp::GridSpec kGrid{{5, 5, 5, 5}, {0, 0, 0, 0}, {1, 1, 1, 1}};

// A stand-in for the simulator: a descriptor and fitness drawn from the
// solution's bits, so that the archive is offered realistic, spread values.
template <class Solution>
std::vector<Evaluation> fake(const std::vector<Solution>& batch, cic::Rng& rng) {
    std::vector<Evaluation> out(batch.size());
    for (auto& e : out) {
        e.descriptor = {rng.uniform(), rng.uniform(), rng.uniform(), rng.uniform()};
        e.fitness = 10 * rng.uniform();
    }
    return out;
}

// Items: solutions made and offered (batches of 50 into a filled archive).
void BM_ArchiveStepGait(benchmark::State& state) {
    cic::gp::VectorMapElitesConfig c{kGrid, 37, 50, 100, 0.1};
    cic::gp::VectorMapElites me(c, 1);
    cic::Rng rng(2);
    auto evaluate = [&](const std::vector<std::vector<double>>& xs) { return fake(xs, rng); };
    for (int i = 0; i < 40; ++i) me.step(evaluate, 1000);   // about 600 of 625 cells filled
    for (auto _ : state) me.step(evaluate, 1000);
    state.SetItemsProcessed(state.iterations() * 50);
}
BENCHMARK(BM_ArchiveStepGait);

// A gait run's settings with the CMA-ME emitter, batches of 50, sigma 0.15.
cic::io::Settings cma_me_settings() {
    return cic::io::read_settings_string(
        "<settings><Experiment><type>gait</type></Experiment><MapElites><enabled>1</enabled>"
        "<emitter>cma-me</emitter><batch>50</batch><initial>100</initial><sigma>0.15</sigma></MapElites></settings>",
        "bench.xml");
}

// The CMA-ME emitter: a CMA-ES generation of 50 over 37 parameters (pagmo's
// cmaes, run twice: once to learn the points, once with their ranks).
void BM_ArchiveStepCmaMe(benchmark::State& state) {
    const cic::io::Settings s = cma_me_settings();
    const cic::gp::VectorMapElitesConfig c{kGrid, 37, 50, 100, 0.15};
    cic::gp::MapElites<std::vector<double>> me({kGrid, 50, 100}, cic::gait::cma_me_emitter(s, c), 1);
    cic::Rng rng(2);
    auto evaluate = [&](const std::vector<std::vector<double>>& xs) { return fake(xs, rng); };
    for (int i = 0; i < 40; ++i) me.step(evaluate, 1000);
    for (auto _ : state) me.step(evaluate, 1000);
    state.SetItemsProcessed(state.iterations() * 50);
}
BENCHMARK(BM_ArchiveStepCmaMe);

// A resume's replay of a CMA-ME start 300 generations long (15,000
// evaluations in batches of 50, the longest a start of the study can be).
void BM_CmaMeResumeReplay(benchmark::State& state) {
    const cic::io::Settings s = cma_me_settings();
    const cic::gp::VectorMapElitesConfig c{kGrid, 37, 50, 100, 0.15};
    std::string text = "cma-me 1\nstart 1\nrestart 0\nx0";
    for (int i = 0; i < 37; ++i) text += " 0.5";
    cic::Rng rng(3);
    for (int g = 0; g < 300; ++g) {
        text += "\ngeneration";
        for (int i = 0; i < 50; ++i) text += " " + std::to_string(rng.uniform());
    }
    text += "\n";
    const auto e = cic::gait::cma_me_emitter(s, c);
    for (auto _ : state) e.load(text);
}
BENCHMARK(BM_CmaMeResumeReplay)->Unit(benchmark::kMillisecond);

void BM_ArchiveStepForest(benchmark::State& state) {
    cic::gp::GpConfig gp;
    gp.trees_per_genotype = 3;
    const cic::tree::PrimitiveSet ps(gp.primitives);
    cic::gp::MapElites<cic::tree::Forest> me({kGrid, 50, 100}, cic::gp::forest_emitter(gp, ps), 1);
    cic::Rng rng(2);
    auto evaluate = [&](const std::vector<cic::tree::Forest>& fs) { return fake(fs, rng); };
    for (int i = 0; i < 40; ++i) me.step(evaluate, 1000);
    for (auto _ : state) me.step(evaluate, 1000);
    state.SetItemsProcessed(state.iterations() * 50);
}
BENCHMARK(BM_ArchiveStepForest);

// One checkpoint of a full archive of 3-tree genotypes (written once per batch).
void BM_ArchiveCheckpoint(benchmark::State& state) {
    cic::gp::GpConfig gp;
    gp.trees_per_genotype = 3;
    const cic::tree::PrimitiveSet ps(gp.primitives);
    cic::gp::MapElites<cic::tree::Forest> me({kGrid, 50, 100}, cic::gp::forest_emitter(gp, ps), 1);
    cic::Rng rng(2);
    for (int i = 0; i < 40; ++i) me.step([&](const auto& fs) { return fake(fs, rng); }, 1000);
    cic::io::ArchiveFile a;
    a.experiment = "hypergp";
    a.batches = me.batches();
    a.evaluations = me.evaluations();
    a.descriptor = "duty-factor";
    a.rng = me.rng().state();
    a.grid = kGrid;
    for (const auto& [cell, e] : me.archive().elites()) a.elites.push_back({cell, e.fitness, e.descriptor, {}, e.solution});
    for (auto _ : state) benchmark::DoNotOptimize(cic::io::to_xml(a));
    state.counters["elites"] = static_cast<double>(a.elites.size());
}
BENCHMARK(BM_ArchiveCheckpoint)->Unit(benchmark::kMillisecond);

// One evaluation as MAP-Elites runs it: R1 (4 legs), 15 s, ground recorded.
void BM_PhysicsEvaluationDutyFactors(benchmark::State& state) {
    const auto robot = cic::sim::preset(1, false);
    cic::sim::SimConfig sim;
    cic::sim::EvalOptions options;
    options.record_ground = true;
    for (auto _ : state) {
        cic::sim::SineController gait({{0.5, 0.5, 0.0}, {0.5, 0.5, 3.14159}});
        auto r = cic::sim::evaluate(robot, gait, sim, options);
        benchmark::DoNotOptimize(cic::sim::duty_factors(robot, r));
    }
}
BENCHMARK(BM_PhysicsEvaluationDutyFactors)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
