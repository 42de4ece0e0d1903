// GP node evaluations per second ("GPops"), measured the way Operon does:
// 1000 random trees of 1-64 nodes over 12,800 rows x 10 variables, with the
// arithmetic set {add, sub, mul, div} and with sin/exp added, on 1 and 2 threads.
// Counter "GPops" = nodes x rows per second.
#include <benchmark/benchmark.h>

#include <vector>

#include "cic/core/parallel_for.hpp"
#include "cic/core/rng.hpp"
#include "cic/tree/eval.hpp"
#include "cic/tree/tree.hpp"

namespace {

using namespace cic;
using namespace cic::tree;

constexpr std::size_t kTrees = 1000;
constexpr std::size_t kRows = 12800;
constexpr int kVariables = 10;

// Appends a random tree of exactly `size` nodes (size >= 1) in postfix order.
void random_tree(Rng& rng, const std::vector<Op>& binary, const std::vector<Op>& unary, std::size_t size,
                 std::vector<Node>& out) {
    if (size == 1) {
        out.push_back(rng.bernoulli(0.5) ? Node::variable(rng.between(0, kVariables - 1))
                                         : Node::constant(rng.uniform(-1.0, 1.0)));
        return;
    }
    if (size == 2 || (!unary.empty() && rng.bernoulli(0.3))) {
        random_tree(rng, binary, unary, size - 1, out);
        out.push_back(Node::function(unary[rng.index(unary.size())]));
        return;
    }
    // Both sides get >= 1 node; without unary functions both sides need odd sizes.
    const std::size_t left = unary.empty() ? 1 + 2 * rng.index((size - 1) / 2) : 1 + rng.index(size - 2);
    random_tree(rng, binary, unary, left, out);
    random_tree(rng, binary, unary, size - 1 - left, out);
    out.push_back(Node::function(binary[rng.index(binary.size())]));
}

std::vector<Tree> make_trees(bool transcendental) {
    const std::vector<Op> binary{Op::Add, Op::Sub, Op::Mul, Op::Div};
    const std::vector<Op> unary = transcendental ? std::vector<Op>{Op::Sin, Op::Exp} : std::vector<Op>{};
    Rng rng(2024);
    std::vector<Tree> trees;
    for (std::size_t i = 0; i < kTrees; ++i) {
        std::size_t size = 1 + rng.index(64);
        if (unary.empty() && size % 2 == 0) --size;   // binary-only trees have odd sizes
        std::vector<Node> nodes;
        random_tree(rng, binary, unary, size, nodes);
        trees.emplace_back(std::move(nodes));
    }
    return trees;
}

struct Data {
    std::vector<std::vector<double>> columns;
    std::vector<const double*> pointers;
    Data() {
        Rng rng(7);
        columns.assign(kVariables, std::vector<double>(kRows));
        for (auto& c : columns)
            for (double& v : c) v = rng.uniform(-10.0, 10.0);
        for (auto& c : columns) pointers.push_back(c.data());
    }
};

void BM_GPops(benchmark::State& state) {
    const bool transcendental = state.range(0) != 0;
    const int threads = static_cast<int>(state.range(1));
    static const Data data;
    const auto trees = make_trees(transcendental);
    std::size_t nodes = 0;
    for (const auto& t : trees) nodes += t.size();
    // Trees are handed out one at a time (cic::parallel_for), each thread writing to its own buffer.
    auto work = [&](std::size_t i) {
        thread_local std::vector<double> out(kRows);
        evaluate(trees[i], data.pointers, kRows, out);
        benchmark::DoNotOptimize(out.data());
    };
    for (auto _ : state) cic::parallel_for(trees.size(), threads, work);
    state.counters["GPops"] = benchmark::Counter(static_cast<double>(nodes) * kRows,
                                                 benchmark::Counter::kIsIterationInvariantRate);
    state.counters["nodes"] = static_cast<double>(nodes);
    state.SetLabel(transcendental ? "+-*/ sin exp" : "+-*/");
}

// Symbolic-regression sized batches (Koza-1 samples 20 points): here the
// per-call set-up, not the loops, dominates.
void BM_SmallBatch(benchmark::State& state) {
    const auto rows = static_cast<std::size_t>(state.range(0));
    static const Data data;
    const auto trees = make_trees(true);
    std::size_t nodes = 0;
    for (const auto& t : trees) nodes += t.size();
    std::vector<double> out(rows);
    for (auto _ : state)
        for (const auto& t : trees) {
            evaluate(t, data.pointers, rows, out);
            benchmark::DoNotOptimize(out.data());
        }
    state.counters["GPops"] = benchmark::Counter(static_cast<double>(nodes) * static_cast<double>(rows),
                                                 benchmark::Counter::kIsIterationInvariantRate);
    state.counters["trees/s"] = benchmark::Counter(static_cast<double>(trees.size()),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

} // namespace

BENCHMARK(BM_SmallBatch)->Arg(20)->Arg(200)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_GPops)->ArgNames({"sinexp", "threads"})->ArgsProduct({{0, 1}, {1, 2}})->UseRealTime()->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
