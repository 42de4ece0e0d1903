// Switch-HybrID (Neural.switchPatience / switchShare; docs/hypergp.md): the
// hand-over point is the exact image of HyperGP-gait's gait in the gait box's
// centred layout (the same fitness bits), the search starts there, and a run
// goes from HyperGP to CMA-ES in one folder, one budget and one checkpoint
// chain: the same bytes for 1 or 2 workers and for a resume before, at or
// after the switch.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "cic/experiments/gait/encoding.hpp"
#include "cic/experiments/gait/search.hpp"
#include "cic/experiments/gait/setup.hpp"
#include "cic/experiments/hypergp/gait_substrate.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/report/replay.hpp"
#include "support/expect_has.hpp"
#include "support/run_helpers.hpp"

namespace cic {
namespace {

using namespace cic::testing;
namespace fs = std::filesystem;

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

fs::path checkpoint(const fs::path& run, int generation) {
    char name[32];
    std::snprintf(name, sizeof name, "gen-%04d.xml", generation);
    return run / "populations" / name;
}

// HyperGP-gait on R0 with 2.5 s simulations, 6 individuals a generation,
// handing over after `patience` generations without improvement or at
// `share` of `evaluations`; CMA-ES with 7 candidates (IPOP).
std::string switch_settings(int evaluations, int workers, const std::string& neural,
                            const std::string& extra_control = "") {
    std::string s = tiny_hypergp_settings(1, workers, extra_control);
    s.replace(s.find("</settings>"), 0,
              "  <Neural><substrate>gait</substrate>" + neural +
                  "</Neural>\n  <Gait><evaluations>" + std::to_string(evaluations) +
                  "</evaluations><populationSize>7</populationSize><restarts>ipop</restarts>"
                  "<restartPatience>2</restartPatience><bounds>reflect</bounds></Gait>\n");
    return s;
}

const char* kPatience = "<switchPatience>2</switchPatience>";

TEST(SwitchHybrid, TheHandoverPointIsTheSameGaitBitForBit) {
    io::Settings s = io::load_settings_text(switch_settings(100, 1, kPatience), "switch.xml", {});
    s.sim.sample_to = 4;
    const gait::Setup setup = gait::Setup::from_settings(s);
    ASSERT_TRUE(setup.encoding.centred);
    const hypergp::Model model = hypergp::Model::from_settings(s);
    const std::size_t n = model.robot.actuated().size();
    const std::vector<tree::Forest> forests = {
        {tree::Tree::parse("(sin (add x0 (mul x2 x3)))")},
        {tree::Tree::parse("(mul x0 -1)"), tree::Tree::parse("(add x1 (gauss x3))"),
         tree::Tree::parse("(atan (mul (sin x0) 0.001))")},   // offsets near 0: the low bits matter
        {tree::Tree::parse("(add x2 (mul x3 7))"), tree::Tree::parse("(mul x0 -30)"), tree::Tree::parse("x1")},
    };
    std::vector<double> d(n);
    for (std::size_t i = 0; i < n; ++i) d[i] = std::sin(3.0 * static_cast<double>(i)) * 0.7;
    int walked = 0;
    for (const auto& f : forests)
        for (const std::vector<double>& offsets : {std::vector<double>{}, d}) {
            const std::vector<double> x = hypergp::gait_box_point(model.robot, f, model.neural, offsets);
            ASSERT_EQ(x.size(), setup.dimension());
            const sim::GaitSpec want = hypergp::gait_spec(model.robot, f, model.neural, offsets);
            const sim::GaitSpec got = setup.encoding.decode(x);
            EXPECT_EQ(bits(got.frequency), bits(want.frequency));
            for (std::size_t j = 0; j < n; ++j) {
                EXPECT_EQ(bits(got.joints[j].amplitude), bits(want.joints[j].amplitude)) << j;
                EXPECT_EQ(bits(got.joints[j].phase), bits(want.joints[j].phase)) << j;
                EXPECT_EQ(bits(got.joints[j].offset), bits(want.joints[j].offset)) << j;
            }
            // The gait experiment's controller walks the HyperGP individual's walk.
            const double hypergp_fitness = hypergp::run(model, f, offsets).fitness;
            const double gait_fitness = sim::evaluate(setup.robot, *setup.controller(x), setup.sim).fitness;
            EXPECT_EQ(bits(gait_fitness), bits(hypergp_fitness));
            walked += hypergp_fitness != 0;
        }
    EXPECT_GT(walked, 0);
    // The standard layout could not: (2x - 1) pi/2 loses an offset's low bits near 0.
    gait::Encoding standard = setup.encoding;
    standard.centred = false;
    const std::vector<double> x = hypergp::gait_box_point(model.robot, forests[1], model.neural);
    std::vector<double> y = x;
    for (std::size_t j = 0; j < n; ++j) y[1 + 3 * j + 2] = (2 * x[1 + 3 * j + 2] + 1) / 2;
    const sim::GaitSpec want = hypergp::gait_spec(model.robot, forests[1], model.neural);
    int inexact = 0;
    for (std::size_t j = 0; j < n; ++j) inexact += bits(standard.decode(y).joints[j].offset) != bits(want.joints[j].offset);
    EXPECT_GT(inexact, 0);
}

TEST(SwitchHybrid, TheCentredLayoutWrapsPhasesAndBoundsOffsets) {
    gait::Encoding e(2, false, 0.1, 3.0, gait::Bounds::Reflect);
    e.centred = true;
    EXPECT_EQ(e.lower(), (std::vector<double>{0, 0, -0.5, -0.5, 0, -0.5, -0.5}));
    const double pi = std::numbers::pi;
    const auto g = e.decode(std::vector<double>{0.5, 0.3, -0.25, 0.25, 1.2, 0.7, 0.6});
    EXPECT_DOUBLE_EQ(g.joints[0].phase, -pi / 2);
    EXPECT_DOUBLE_EQ(g.joints[0].offset, pi / 4);
    EXPECT_DOUBLE_EQ(g.joints[1].amplitude, 0.8 * pi / 2);   // reflected at 1
    EXPECT_NEAR(g.joints[1].phase, 2 * pi * -0.3, 1e-12);     // periodic
    EXPECT_NEAR(g.joints[1].offset, pi / 2 * 2 * 0.4, 1e-12); // reflected at 1/2
    gait::Encoding standard(2, false, 0.1, 3.0);
    EXPECT_EQ(standard.lower(), std::vector<double>(7, 0.0));
}

TEST(SwitchHybrid, TheSearchStartsAtItsStartPoint) {
    gait::Search bad(gait::Optimizer::Cmaes, 3, 6, 0.1, 5);
    EXPECT_THROW(bad.set_start({0.5, 0.5}), std::invalid_argument);
    EXPECT_THROW(bad.set_start({0.5, NAN, 0.5}), std::invalid_argument);
    EXPECT_THROW(bad.set_box({0.0, 0.0}), std::invalid_argument);
    const std::vector<double> x0{0.3, -0.2, 0.45};
    auto f = [](const std::vector<std::vector<double>>& xs) {
        std::vector<double> out;
        for (const auto& x : xs) out.push_back(-std::abs(x[0] - 0.25) - std::abs(x[1]) - std::abs(x[2] - 0.4));
        return out;
    };
    // Every optimiser Switch-HybrID may hand over to (settings_validate: not sade).
    for (const gait::Optimizer o : {gait::Optimizer::Cmaes, gait::Optimizer::Xnes, gait::Optimizer::Sepcmaes}) {
        SCOPED_TRACE(gait::to_string(o));
        auto run = [&] {
            gait::Search s(o, 3, 6, 0.1, 5);
            s.set_box({0.0, -0.5, -0.5});
            s.set_start(x0);
            s.initialise(f);
            for (int g = 0; g < 4; ++g) s.step(f);
            return s;
        };
        const gait::Search a = run(), b = run();
        EXPECT_EQ(a.history(), b.history());
        EXPECT_EQ(a.start_point(), x0);
        EXPECT_EQ(a.history().front(), f({x0}).front());   // x0 is the first point evaluated
        EXPECT_GE(a.champion().fitness, f({x0}).front());
        // A replay with the start point gives the same state back.
        gait::Search c(o, 3, 6, 0.1, 5);
        c.set_box({0.0, -0.5, -0.5});
        c.set_start(x0);
        c.replay(a.history(), a.generation());
        EXPECT_EQ(c.champion().x, a.champion().x);
        ASSERT_EQ(c.population().size(), a.population().size());
        for (std::size_t i = 0; i < c.population().size(); ++i)
            EXPECT_EQ(c.population()[i].x, a.population()[i].x);
    }
}

int rows_of(const fs::path& stats) {
    std::ifstream in(stats);
    std::string line;
    int rows = -1, expected = 0;
    while (std::getline(in, line)) {
        if (rows >= 0) {
            EXPECT_EQ(std::stoi(line.substr(0, line.find(','))), expected++) << line;
        }
        ++rows;
    }
    return rows;
}

TEST(SwitchHybrid, OneRunHandsOverInOneFolderWithTheSameBytesForAnyWorkers) {
    const auto dir = temp_dir("switch-run");
    const auto one = run_settings(dir, "one", switch_settings(90, 1, kPatience));
    const auto two = run_settings(dir, "two", switch_settings(90, 2, kPatience));
    ASSERT_EQ(one.rc, 0) << one.log;
    ASSERT_EQ(two.rc, 0) << two.log;
    EXPECT_EQ(read_text(one.run / "population.xml"), read_text(two.run / "population.xml"));
    EXPECT_EQ(read_text(one.run / "summary.txt").substr(0, 200), read_text(two.run / "summary.txt").substr(0, 200));
    const std::string log = read_text(one.run / "run.log");
    const std::smatch m = [&] {
        std::smatch out;
        std::regex_search(log, out, std::regex("switch: HyperGP hands over after generation (\\d+) \\((\\d+) evaluations\\)"));
        return out;
    }();
    ASSERT_EQ(m.size(), 3u) << log;
    const int g = std::stoi(m[1]);
    const long e = std::stol(m[2]);
    // The last HyperGP checkpoint, then gait checkpoints, numbered on.
    const io::PopulationFile last_gp = io::load_population(checkpoint(one.run, g));
    ASSERT_TRUE(last_gp.switch_clock.has_value());
    EXPECT_GE(g - last_gp.switch_clock->best_generation, 2);
    const io::GaitFile first_gait = io::load_gait(checkpoint(one.run, g + 1));
    ASSERT_TRUE(first_gait.handover.has_value());
    EXPECT_EQ(first_gait.handover->generation, g);
    EXPECT_EQ(first_gait.handover->evaluations, e);
    // CMA-ES's first point is HyperGP's best, which walks the same bits there.
    EXPECT_EQ(bits(first_gait.history.front()), bits(last_gp.population.best().fitness));
    const io::GaitFile last = io::load_gait(one.run / "population.xml");
    EXPECT_LE(e + last.evaluations, 90);
    EXPECT_NE(read_text(one.run / "summary.txt").find("stopped: evaluation budget"), std::string::npos)
        << read_text(one.run / "summary.txt");   // the budget is spent: the next batch would pass it
    EXPECT_GE(last.champion.fitness, last_gp.population.best().fitness);
    // stats.csv: one row per generation, numbered on across the switch.
    EXPECT_EQ(rows_of(one.run / "stats.csv"), g + 1 + last.generation + 1);
    // view, trace and assess replay the champion to its stored fitness.
    const auto items = report::replay(one.run.string(), "best", 1, 0.0, false);
    ASSERT_EQ(items.size(), 1u);
    EXPECT_EQ(items[0].replayed_fitness, last.champion.fitness);
    fs::remove_all(dir);
}

// The processes whose parent is `pid` (its worker processes).
int children_of(pid_t pid) {
    int n = 0;
    for (const auto& e : fs::directory_iterator("/proc")) {
        const std::string name = e.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        std::ifstream in(e.path() / "stat");
        std::string stat;
        std::getline(in, stat);
        const auto close = stat.rfind(')');
        if (close == std::string::npos) continue;
        std::istringstream rest(stat.substr(close + 2));
        char state = 0;
        pid_t parent = 0;
        rest >> state >> parent;
        n += parent == pid && state != 'Z';
    }
    return n;
}

// Issue 56: the gait phase runs with Experiment.workers worker processes, not
// with the HyperGP phase's kept beside its own.
TEST(SwitchHybrid, EachPhaseHasItsWorkersAndNoMore) {
    const auto dir = temp_dir("switch-workers");
    write_text(dir / "s.xml", switch_settings(400, 1, kPatience));
    const pid_t pid = start_cic(dir / "s.xml", dir / "out", dir / "s.log", "");
    ASSERT_GT(pid, 0);
    int most = 0, samples = 0;
    for (int status = 0; waitpid(pid, &status, WNOHANG) == 0;) {
        fs::path run;
        if (fs::exists(dir / "out")) run = only_run(dir / "out");
        if (!run.empty() && read_text(run / "run.log").find("switch: HyperGP hands over") != std::string::npos) {
            most = std::max(most, children_of(pid));
            ++samples;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_GT(samples, 0) << read_text(dir / "s.log");
    EXPECT_EQ(most, 1) << "worker processes in the gait phase with workers=1";
    fs::remove_all(dir);
}

TEST(SwitchHybrid, ResumingBeforeAtOrAfterTheSwitchGivesTheSameBytes) {
    const auto dir = temp_dir("switch-resume");
    const auto whole = run_settings(dir, "whole", switch_settings(90, 1, kPatience));
    ASSERT_EQ(whole.rc, 0) << whole.log;
    const std::string want = read_text(whole.run / "population.xml");
    const std::string log = read_text(whole.run / "run.log");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(log, m, std::regex("hands over after generation (\\d+)"))) << log;
    const int g = std::stoi(m[1]);
    ASSERT_GE(g, 2);
    // Before (a HyperGP checkpoint), at (the last one), after (the first gait
    // one) and at the end (the run's final checkpoint: the resume ends at once).
    const io::GaitFile final_state = io::load_gait(whole.run / "population.xml");
    const int last = g + 1 + final_state.generation;
    for (int from : {g - 1, g, g + 1, last}) {
        const fs::path file = checkpoint(whole.run, from);
        ASSERT_TRUE(fs::exists(file)) << file;
        const auto r = run_settings(dir, "from" + std::to_string(from),
                                    switch_settings(90, 2, kPatience, "<populationXmlLoadFrom>" + file.string() +
                                                                          "</populationXmlLoadFrom>"));
        ASSERT_EQ(r.rc, 0) << r.log;
        EXPECT_EQ(read_text(r.run / "population.xml"), want) << "resumed from generation " << from;
        // Resumed before or after the switch, the summary names both phases, as the whole run's does.
        const std::string summary = read_text(r.run / "summary.txt");
        EXPECT_EQ(summary.rfind("HyperGP phase:\n", 0), 0u) << "resumed from generation " << from << "\n" << summary;
        EXPECT_HAS(summary, "\n\ngait phase (cmaes from the best's gait):\nstopped: ");
    }
    // `cic resume` in place: a smaller budget, then the rest.
    const auto part = run_settings(dir, "part", switch_settings(60, 1, kPatience));
    ASSERT_EQ(part.rc, 0) << part.log;
    const int rc = run_command("resume --quiet " + part.run.string() + " --set Gait.evaluations=90", dir / "resume.log");
    ASSERT_EQ(rc, 0) << read_text(dir / "resume.log");
    // Patience handed over at the same generation under either budget, so the rest is the same search.
    ASSERT_NE(read_text(part.run / "run.log").find("hands over after generation " + std::to_string(g) + " "),
              std::string::npos) << read_text(part.run / "run.log");
    EXPECT_EQ(read_text(part.run / "population.xml"), want);
    fs::remove_all(dir);
}

// The gait phase may be the separable CMA-ES of the direct side (issue 38's
// tuning): the same start point, bytes and resume as with full CMA-ES.
TEST(SwitchHybrid, HandingOverToSeparableCmaesKeepsTheStartAndTheBytes) {
    const auto dir = temp_dir("switch-sep");
    auto settings = [](int workers, const std::string& control = "") {
        std::string s = switch_settings(90, workers, kPatience, control);
        s.replace(s.find("<restarts>"), 0, "<optimizer>sepcmaes</optimizer>");
        return s;
    };
    const auto one = run_settings(dir, "one", settings(1));
    const auto two = run_settings(dir, "two", settings(2));
    ASSERT_EQ(one.rc, 0) << one.log;
    ASSERT_EQ(two.rc, 0) << two.log;
    const std::string want = read_text(one.run / "population.xml");
    EXPECT_EQ(read_text(two.run / "population.xml"), want);
    const std::string log = read_text(one.run / "run.log");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(log, m, std::regex("hands over after generation (\\d+) .*; sepcmaes starts from"))) << log;
    const int g = std::stoi(m[1]);
    EXPECT_NE(read_text(one.run / "summary.txt").find("gait phase (sepcmaes from the best's gait):"), std::string::npos)
        << read_text(one.run / "summary.txt");
    const io::PopulationFile last_gp = io::load_population(checkpoint(one.run, g));
    const io::GaitFile first_gait = io::load_gait(checkpoint(one.run, g + 1));
    EXPECT_EQ(first_gait.optimizer, "sepcmaes");
    EXPECT_EQ(bits(first_gait.history.front()), bits(last_gp.population.best().fitness));
    // Resumed from the first gait checkpoint with two workers: the same bytes.
    const auto resumed = run_settings(dir, "resumed", settings(2, "<populationXmlLoadFrom>" +
                                                                  checkpoint(one.run, g + 1).string() +
                                                                  "</populationXmlLoadFrom>"));
    ASSERT_EQ(resumed.rc, 0) << resumed.log;
    EXPECT_EQ(read_text(resumed.run / "population.xml"), want);
    fs::remove_all(dir);
}

// SIGKILL at moments before, around and after the hand-over, then a resume
// from whatever checkpoint was left: the bytes of the unbroken run.
TEST(SwitchHybrid, KilledAnywhereAndResumedGivesTheSameBytes) {
    const auto dir = temp_dir("switch-kill");
    const auto whole = run_settings(dir, "whole", switch_settings(90, 2, kPatience));
    ASSERT_EQ(whole.rc, 0) << whole.log;
    const std::string want = read_text(whole.run / "population.xml");
    write_text(dir / "s.xml", switch_settings(90, 2, kPatience));
    int resumed_from_gait = 0;
    for (int k = 0; k < 4; ++k) {
        fs::path resumed, from;
        ASSERT_TRUE(kill_then_resume(dir, dir / "s.xml", k, 0.25 + 0.3 * k, true, resumed, from))
            << read_text(dir / "resumed.log");
        EXPECT_EQ(read_text(resumed / "population.xml"), want) << "killed at " << 0.25 + 0.3 * k << " s, from " << from;
        resumed_from_gait += !from.empty() && io::is_gait_file(from);
    }
    RecordProperty("resumed_from_gait_checkpoints", resumed_from_gait);
    fs::remove_all(dir);
}

TEST(SwitchHybrid, AShareOfTheBudgetHandsOver) {
    const auto dir = temp_dir("switch-share");
    const auto r = run_settings(dir, "share", switch_settings(100, 1, "<switchShare>0.3</switchShare>"));
    ASSERT_EQ(r.rc, 0) << r.log;
    const std::string log = read_text(r.run / "run.log");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(log, m, std::regex("hands over after generation (\\d+) \\((\\d+) evaluations\\)")))
        << log;
    EXPECT_GE(std::stol(m[2]), 30);
    EXPECT_LT(std::stol(m[2]), 30 + 6 + 6);
    fs::remove_all(dir);
}

TEST(SwitchHybrid, SettingsThatCannotHandOverExactlyAreRefused) {
    const auto dir = temp_dir("switch-refused");
    std::string network = switch_settings(90, 1, kPatience);
    network.replace(network.find("<substrate>gait</substrate>"), std::string("<substrate>gait</substrate>").size(), "");
    const auto a = run_settings(dir, "network", network);
    EXPECT_EQ(a.rc, 2) << a.log;
    EXPECT_TRUE(a.run.empty());
    std::string freq = switch_settings(90, 1, std::string(kPatience) + "<frequencyMax>2</frequencyMax>");
    const auto b = run_settings(dir, "freq", freq);
    EXPECT_EQ(b.rc, 2) << b.log;
    EXPECT_NE(b.log.find("both phases read one frequency range"), std::string::npos) << b.log;
    fs::remove_all(dir);
}

} // namespace
} // namespace cic
