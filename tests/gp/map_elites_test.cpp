// The MAP-Elites loop's contract with an emitter that learns (gp/map_elites.hpp):
// an incomplete emitter is refused; `ask` makes the varied part of each batch
// and `tell` hears, in batch order, what became of each (a new cell, an
// improved cell, not kept, failed) with the gain over the cell's elite; the
// emitter's state goes through emitter_state() and restore().
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cic/gp/map_elites.hpp"

namespace cic::gp {
namespace {

using Vector = std::vector<double>;

// Descriptor: x[0]; fitness: x[1]; x[1] < 0 fails.
std::vector<Evaluation> evaluate(const std::vector<Vector>& xs) {
    std::vector<Evaluation> out;
    for (const auto& x : xs) out.push_back({x[1], {x[0]}, x[1] < 0});
    return out;
}

// An emitter that asks for a scripted batch and records what it is told.
struct Script {
    std::vector<std::vector<Vector>> batches;   // what each ask returns
    std::vector<std::vector<Outcome>> told;
    int asked = 0;
};

Emitter<Vector> scripted(Script& s) {
    Emitter<Vector> e;
    e.random = [](Rng&) { return Vector{0.05, 1.0}; };   // cell 0, fitness 1
    e.ask = [&s](Rng&, const GridArchive<Vector>&, std::size_t count) {
        EXPECT_EQ(count, s.batches.at(static_cast<std::size_t>(s.asked)).size());
        return s.batches.at(static_cast<std::size_t>(s.asked++));
    };
    e.tell = [&s](const std::vector<Outcome>& o) { s.told.push_back(o); };
    e.save = [&s] { return "asked " + std::to_string(s.asked); };
    e.load = [&s](const std::string& text) {
        if (text.empty()) return;
        if (text.rfind("asked ", 0) != 0) throw std::invalid_argument("bad state");
        s.asked = std::stoi(text.substr(6));
    };
    return e;
}

MapElitesConfig config() { return {GridSpec{{10}, {0}, {1}}, 4, 4}; }

TEST(MapElitesLoop, AnIncompleteEmitterIsRefused) {
    Script s;
    Emitter<Vector> e = scripted(s);
    e.tell = nullptr;   // asks without listening
    EXPECT_THROW(MapElites<Vector>(config(), e, 1), std::invalid_argument);
    e = scripted(s);
    e.load = nullptr;   // saves what it cannot load
    EXPECT_THROW(MapElites<Vector>(config(), e, 1), std::invalid_argument);
    e = scripted(s);
    e.ask = nullptr;
    e.tell = nullptr;   // neither vary nor ask
    EXPECT_THROW(MapElites<Vector>(config(), e, 1), std::invalid_argument);
    Emitter<Vector> plain;
    plain.random = [](Rng&) { return Vector{0.5, 1.0}; };
    plain.vary = [](Rng&, const GridArchive<Vector>&) { return Vector{0.5, 1.0}; };
    MapElites<Vector> me(config(), plain, 1);
    EXPECT_EQ(me.emitter_state(), "");
    EXPECT_THROW(me.restore({}, 0, 0, 0, Rng(1).state(), "a state"), std::invalid_argument);
}

TEST(MapElitesLoop, TheEmitterIsToldWhatBecameOfEachSolutionInBatchOrder) {
    Script s;
    // Cell 0 holds fitness 1 after the first (random) batch. Then: a new cell,
    // a better one in cell 0, a worse one in cell 0, a failure.
    s.batches = {{{0.55, 2.0}, {0.05, 1.5}, {0.08, 0.5}, {0.9, -1.0}}};
    MapElites<Vector> me(config(), scripted(s), 7);
    me.step(evaluate, 100);   // 4 random: no ask, no tell
    EXPECT_EQ(s.asked, 0);
    EXPECT_TRUE(s.told.empty());
    EXPECT_EQ(me.step(evaluate, 100), 2);
    ASSERT_EQ(s.told.size(), 1u);
    const auto& o = s.told[0];
    ASSERT_EQ(o.size(), 4u);
    EXPECT_EQ(o[0].kind, Outcome::Kind::NewCell);
    EXPECT_EQ(o[0].improvement, 2.0);
    EXPECT_EQ(o[1].kind, Outcome::Kind::Improved);
    EXPECT_EQ(o[1].improvement, 0.5);
    EXPECT_EQ(o[2].kind, Outcome::Kind::NotKept);
    EXPECT_EQ(o[2].improvement, -1.0);   // against the improved elite, 1.5
    EXPECT_EQ(o[3].kind, Outcome::Kind::Failed);
    EXPECT_EQ(me.failed(), 1);
}

TEST(MapElitesLoop, ABatchPastTheInitialOnesIsAskedForItsVariedPartOnly) {
    Script s;
    s.batches = {{{0.3, 1.0}, {0.4, 1.0}}};
    MapElitesConfig c = config();
    c.initial = 6;   // the second batch: 2 random, then 2 asked
    MapElites<Vector> me(c, scripted(s), 7);
    me.step(evaluate, 100);
    me.step(evaluate, 100);
    ASSERT_EQ(s.told.size(), 1u);
    EXPECT_EQ(s.told[0].size(), 2u);
    EXPECT_EQ(me.evaluations(), 8);
}

TEST(MapElitesLoop, TheEmittersStateGoesThroughACheckpoint) {
    Script s;
    s.batches = {{{0.3, 1.0}, {0.4, 1.0}, {0.5, 1.0}, {0.6, 1.0}}, {{0.7, 1.0}, {0.8, 1.0}, {0.9, 1.0}, {0.2, 1.0}}};
    MapElites<Vector> me(config(), scripted(s), 7);
    me.step(evaluate, 100);
    me.step(evaluate, 100);
    EXPECT_EQ(me.emitter_state(), "asked 1");
    Script t;
    t.batches = s.batches;
    MapElites<Vector> resumed(config(), scripted(t), 99);
    resumed.restore(me.archive().elites(), me.evaluations(), me.failed(), me.batches(), me.rng().state(),
                    me.emitter_state());
    EXPECT_EQ(t.asked, 1);
    resumed.step(evaluate, 100);
    me.step(evaluate, 100);
    EXPECT_EQ(resumed.archive().filled(), me.archive().filled());
    Script u;
    MapElites<Vector> bad(config(), scripted(u), 1);
    EXPECT_THROW(bad.restore({}, 0, 0, 0, Rng(1).state(), "nonsense"), std::invalid_argument);
}

} // namespace
} // namespace cic::gp
