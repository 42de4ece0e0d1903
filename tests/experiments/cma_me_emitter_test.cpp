// CMA-ME's improvement emitter (MapElites.emitter = cma-me,
// experiments/gait/cma_me_emitter.cpp) on a synthetic problem: settings it
// cannot run with are refused, a state it could not have saved is refused,
// the same seed gives the same archive, a checkpoint continues bit for bit,
// it stays in the unit box, climbs, and restarts when a generation adds nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cic/core/error.hpp"
#include "cic/core/rng.hpp"
#include "cic/experiments/map_elites_emitters.hpp"
#include "cic/io/settings_io.hpp"

namespace cic {
namespace {

using Vector = std::vector<double>;

// Descriptor: the first two parameters; fitness: closeness of the rest to 0.3.
std::vector<gp::Evaluation> synthetic(const std::vector<Vector>& xs) {
    std::vector<gp::Evaluation> out;
    for (const auto& x : xs) {
        gp::Evaluation e;
        e.descriptor = {x[0], x[1]};
        for (std::size_t i = 2; i < x.size(); ++i) e.fitness -= (x[i] - 0.3) * (x[i] - 0.3);
        out.push_back(e);
    }
    return out;
}

io::Settings settings(int batch = 10, int initial = 20, std::uint64_t seed = 5) {
    return io::read_settings_string("<settings><Experiment><type>gait</type><seed>" + std::to_string(seed) +
                                        "</seed></Experiment><MapElites><enabled>1</enabled><emitter>cma-me</emitter>"
                                        "<batch>" + std::to_string(batch) + "</batch><initial>" +
                                        std::to_string(initial) + "</initial><sigma>0.2</sigma></MapElites></settings>",
                                    "cma-me.xml");
}

gp::VectorMapElitesConfig config(const io::Settings& s, int bins = 10) {
    gp::VectorMapElitesConfig c;
    c.grid = gp::GridSpec{{bins, bins}, {0, 0}, {1, 1}};
    c.dimension = 6;
    c.batch = s.map_elites.batch;
    c.initial = s.map_elites.initial;
    c.sigma = s.map_elites.sigma;
    return c;
}

gp::MapElites<Vector> search(const io::Settings& s, int bins = 10) {
    const auto c = config(s, bins);
    return gp::MapElites<Vector>({c.grid, c.batch, c.initial}, experiments::make_vector_emitter(s, c),
                                 s.experiment.seed);
}

TEST(CmaMeEmitter, SettingsItCannotRunWithAreRefused) {
    EXPECT_NO_THROW(experiments::check_emitter(settings()));
    try {
        experiments::check_emitter(settings(4, 20));
        FAIL() << "a population of 4 was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("batch >= 5"), std::string::npos) << e.what();
    }
    try {
        experiments::check_emitter(settings(10, 25));
        FAIL() << "initial 25 with batches of 10 was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("multiple of batch"), std::string::npos) << e.what();
    }
}

TEST(CmaMeEmitter, AStateItCouldNotHaveSavedIsRefused) {
    const io::Settings s = settings();
    const auto e = experiments::make_vector_emitter(s, config(s));
    const std::string x0 = "x0 0.1 0.2 0.3 0.4 0.5 0.6\n";
    const std::string ten = "generation 1 2 3 4 5 6 7 8 9 10\n";
    EXPECT_NO_THROW(e.load(""));
    EXPECT_NO_THROW(e.load("cma-me 1\nstart 2\nrestart 0\n" + x0 + ten));
    for (const std::string& bad : std::vector<std::string>{"cma-me 2\nstart 1\nrestart 0\n" + x0, "cma-me 1\nstart 0\nrestart 0\n" + x0,
                                  "cma-me 1\nstart 1x\nrestart 0\n" + x0, "cma-me 1\nstart 1\nrestart 2\n" + x0,
                                  std::string("cma-me 1\nstart 1\nrestart 0\nx0 0.1 0.2\n"),
                                  "cma-me 1\nstart 1\nrestart 0\n" + x0 + "generation 1 2 3\n",
                                  "cma-me 1\nstart 1\nrestart 0\n" + x0 + "generation 1 2 3 4 5 6 7 8 9 nan\n",
                                  "cma-me 1\nstart 1\nrestart 0\n" + x0 + "generations 1 2 3 4 5 6 7 8 9 10\n",
                                  "cma-me 1\nstart 1\nrestart 0\nx0 0.1 0.2 0.3 0.4 0.5 1e999\n",
                                  "cma-me 1\nstart 1\nrestart 0\nx0 0.1 0.2 0.3 0.4 0.5 1.5\n",
                                  "cma-me 1\nstart 99999999999\nrestart 0\n" + x0,
                                  "cma-me 1\nstart 2147483647\nrestart 0\n" + x0}) {
        SCOPED_TRACE(bad);
        EXPECT_THROW(e.load(bad), std::invalid_argument);
    }
}

// The fuzz targets do not link the experiments layer, so the state parser gets
// its mangled inputs here (and under ASan and UBSan in CI): a saved state with
// bytes changed, removed, inserted, or lines repeated or cut, is either read or
// refused with std::invalid_argument, never anything else; a state it reads
// saves back to a state that reads back the same, and the search goes on from it.
TEST(CmaMeEmitter, MangledStatesAreReadOrRefusedNeverAnythingElse) {
    const io::Settings s = settings();
    auto run = search(s);
    for (int i = 0; i < 6; ++i) run.step(synthetic, 10000);
    const std::string good = run.emitter_state();
    ASSERT_NE(good.find("generation"), std::string::npos) << good;
    const auto e = experiments::make_vector_emitter(s, config(s));
    using namespace std::string_literals;
    const std::string alphabet = "0123456789.-+eE xn\nagiostr\0\xff"s;   // a NUL and a stray byte too
    Rng rng(11);
    int read = 0, refused = 0;
    for (int trial = 0; trial < 1500; ++trial) {
        std::string text = good;
        for (int edits = rng.between(1, 3); edits > 0 && !text.empty(); --edits) {
            const std::size_t at = rng.index(text.size());
            switch (rng.between(0, 4)) {
            case 0: text[at] = alphabet[rng.index(alphabet.size())]; break;
            case 1: text.erase(at, rng.between(1, 8)); break;
            case 2: text.insert(at, 1, alphabet[rng.index(alphabet.size())]); break;
            case 3: {   // a line repeated
                const std::size_t from = text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
                const std::size_t to = text.find('\n', at);
                if (to != std::string::npos) text.insert(to + 1, text.substr(from, to + 1 - from));
                break;
            }
            default: text.resize(at); break;
            }
        }
        SCOPED_TRACE(text);
        try {
            e.load(text);
        } catch (const std::invalid_argument&) {
            ++refused;
            continue;
        }
        ++read;
        const std::string saved = e.save();
        ASSERT_NO_THROW(e.load(saved));
        EXPECT_EQ(e.save(), saved);
        if (read <= 20 && !saved.empty()) {   // the search goes on from what was read
            auto resumed = search(s);
            resumed.restore(run.archive().elites(), run.evaluations(), run.failed(), run.batches(), run.rng().state(),
                            saved);
            for (int i = 0; i < 2; ++i) resumed.step(synthetic, 10000);
            for (const auto& [cell, elite] : resumed.archive().elites())
                for (double v : elite.solution) ASSERT_TRUE(v >= 0.0 && v <= 1.0) << v;
        }
    }
    EXPECT_GT(read, 0);      // some edits keep a readable state (a digit for a digit)
    EXPECT_GT(refused, 0);
}

TEST(CmaMeEmitter, TheSameSeedGivesTheSameArchive) {
    auto a = search(settings()), b = search(settings()), c = search(settings(10, 20, 6));
    for (int i = 0; i < 12; ++i)
        for (auto* me : {&a, &b, &c}) me->step(synthetic, 1000);
    ASSERT_EQ(a.archive().filled(), b.archive().filled());
    for (const auto& [cell, e] : a.archive().elites()) EXPECT_EQ(b.archive().at(cell)->solution, e.solution);
    EXPECT_EQ(a.emitter_state(), b.emitter_state());
    EXPECT_NE(a.archive().qd_score(-10), c.archive().qd_score(-10));
}

TEST(CmaMeEmitter, ACheckpointContinuesBitForBit) {
    auto whole = search(settings());
    for (int i = 0; i < 9; ++i) whole.step(synthetic, 10000);
    const auto elites = whole.archive().elites();
    const long evaluations = whole.evaluations(), failed = whole.failed();
    const int batches = whole.batches();
    const Rng::State rng = whole.rng().state();
    const std::string state = whole.emitter_state();
    ASSERT_EQ(state.rfind("cma-me 1\nstart ", 0), 0u) << state;
    for (int i = 0; i < 9; ++i) whole.step(synthetic, 10000);

    auto resumed = search(settings());
    resumed.restore(elites, evaluations, failed, batches, rng, state);
    for (int i = 0; i < 9; ++i) resumed.step(synthetic, 10000);
    EXPECT_EQ(resumed.emitter_state(), whole.emitter_state());
    ASSERT_EQ(resumed.archive().filled(), whole.archive().filled());
    for (const auto& [cell, e] : whole.archive().elites()) {
        EXPECT_EQ(resumed.archive().at(cell)->solution, e.solution);
        EXPECT_EQ(resumed.archive().at(cell)->fitness, e.fitness);
    }
}

TEST(CmaMeEmitter, ItStaysInTheUnitBoxClimbsAndRestartsWhenNothingIsAdded) {
    auto me = search(settings(10, 20));
    while (me.evaluations() < 2000) me.step(synthetic, 2000 - me.evaluations());
    for (const auto& [cell, e] : me.archive().elites())
        for (double v : e.solution) EXPECT_TRUE(v >= 0.0 && v <= 1.0) << v;
    EXPECT_GT(me.archive().best()->fitness, -0.01);
    // On a grid of one cell a generation soon adds nothing: the emitter restarts.
    auto one = search(settings(10, 20), 1);
    for (int i = 0; i < 60; ++i) one.step(synthetic, 10000);
    const std::string state = one.emitter_state();
    const int start = std::stoi(state.substr(state.find("start ") + 6));
    EXPECT_GT(start, 1) << state.substr(0, 40);
}

} // namespace
} // namespace cic
