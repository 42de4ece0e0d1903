// Offset-HybrID (Neural.directOffsets; docs/hypergp.md): the gait substrate
// with one directly encoded offset per joint. The offsets change the gait as
// the formula says; a run carries them through workers, population files,
// resumes and replays bit for bit; settings and files that do not fit are refused.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>

#include "cic/experiments/hypergp/controller.hpp"
#include "cic/experiments/hypergp/gait_substrate.hpp"
#include "cic/experiments/hypergp/model.hpp"
#include "cic/experiments/hypergp/queries.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/report/export.hpp"
#include "cic/report/replay.hpp"
#include "cic/core/error.hpp"
#include "support/expect_has.hpp"
#include "support/files.hpp"
#include "support/run_helpers.hpp"

namespace cic {
namespace {

using namespace cic::testing;
namespace fs = std::filesystem;
constexpr double kHalfPi = std::numbers::pi / 2;

TEST(OffsetHybrid, TheOffsetsMoveEachJointsOffsetAndNothingElse) {
    const auto robot = sim::preset(1, false);
    nn::NeuralConfig cfg;
    cfg.substrate = "gait";
    const tree::Forest f{tree::Tree::parse("(sin (add x0 x2))"), tree::Tree::parse("x1"),
                         tree::Tree::parse("(mul x0 0.3)")};
    const std::size_t n = robot.actuated().size();
    const sim::GaitSpec plain = hypergp::gait_spec(robot, f, cfg);
    std::vector<double> d(n);
    for (std::size_t i = 0; i < n; ++i) d[i] = -1.5 + 0.25 * static_cast<double>(i);
    const sim::GaitSpec shifted = hypergp::gait_spec(robot, f, cfg, d);
    ASSERT_EQ(shifted.joints.size(), n);
    EXPECT_EQ(shifted.frequency, plain.frequency);
    int moved = 0;
    for (std::size_t i = 0; i < n; ++i) {
        EXPECT_EQ(shifted.joints[i].amplitude, plain.joints[i].amplitude);
        EXPECT_EQ(shifted.joints[i].phase, plain.joints[i].phase);
        const double tree_part = plain.joints[i].offset / kHalfPi;
        EXPECT_DOUBLE_EQ(shifted.joints[i].offset, kHalfPi * std::clamp(tree_part + d[i], -1.0, 1.0));
        moved += shifted.joints[i].offset != plain.joints[i].offset;
    }
    EXPECT_GE(moved, static_cast<int>(n) - 1);
    // Zero offsets are the plain gait, bit for bit.
    const sim::GaitSpec zero = hypergp::gait_spec(robot, f, cfg, std::vector<double>(n, 0.0));
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(zero.joints[i].offset, plain.joints[i].offset);
    // The controller holds the moved offsets: its command at t = 0 differs.
    auto a = hypergp::make_controller(robot, f, cfg, 0.0125);
    auto b = hypergp::make_controller(robot, f, cfg, 0.0125, d);
    std::vector<double> angles(n), ca(n), cb(n);
    a->step(0.0, angles, ca);
    b->step(0.0, angles, cb);
    EXPECT_NE(ca, cb);
}

TEST(OffsetHybrid, BadOffsetsAndSubstratesWithoutThemThrow) {
    const auto robot = sim::preset(1, false);
    nn::NeuralConfig cfg;
    cfg.substrate = "gait";
    const tree::Forest f{tree::Tree::parse("x0")};
    const std::size_t n = robot.actuated().size();
    EXPECT_THROW(hypergp::gait_spec(robot, f, cfg, std::vector<double>(n - 1, 0.0)), std::invalid_argument);
    std::vector<double> nan(n, 0.0);
    nan[2] = NAN;
    EXPECT_THROW(hypergp::gait_spec(robot, f, cfg, nan), std::invalid_argument);
    cfg.substrate = "cpg";
    EXPECT_THROW(hypergp::make_controller(robot, f, cfg, 0.0125, std::vector<double>(n, 0.0)), std::invalid_argument);
    EXPECT_TRUE(hypergp::takes_direct_offsets("gait"));
    EXPECT_FALSE(hypergp::takes_direct_offsets("network"));
}

TEST(OffsetHybrid, TheJobTextCarriesTheExactOffsets) {
    const tree::Forest f{tree::Tree::parse("(add x0 1)")};
    const std::vector<double> d{0.1, -1.0 / 3.0, 2.0, -0.0, 1e-300};
    const hypergp::Job job = hypergp::parse_job_body(hypergp::job_body(f, sim::Descriptor::DutyFactor, d));
    EXPECT_EQ(job.offsets, d);
    EXPECT_EQ(job.genotype, f);
    EXPECT_EQ(job.descriptor, sim::Descriptor::DutyFactor);
    EXPECT_TRUE(hypergp::parse_job_body(hypergp::job_body(f)).offsets.empty());
    EXPECT_THROW(hypergp::parse_job_body("offsets 1 2\n(add x0 1)\n"), std::invalid_argument);
    EXPECT_THROW(hypergp::parse_job_body("(add x0 1)\noffsets 1 x\n"), std::invalid_argument);
    EXPECT_THROW(hypergp::parse_job_body("(add x0 1)\noffsets 1 inf\n"), std::invalid_argument);
    EXPECT_THROW(hypergp::parse_job_body("(add x0 1)\noffsets 1\n(add x0 2)\n"), std::invalid_argument);
}

// tiny_hypergp_settings on the gait substrate with direct offsets (R0).
std::string offset_settings(int generations, int workers, const std::string& extra_control = "") {
    std::string s = tiny_hypergp_settings(generations, workers, extra_control);
    s.replace(s.find("</settings>"), 0,
              "  <Neural><substrate>gait</substrate><directOffsets>1</directOffsets><offsetSigma>0.3</offsetSigma>"
              "<offsetRate>0.5</offsetRate></Neural>\n");
    return s;
}

TEST(OffsetHybrid, OneAndTwoWorkersGiveIdenticalPopulationsWithOffsets) {
    const auto dir = temp_dir("offset-workers");
    const auto one = run_settings(dir, "one", offset_settings(3, 1));
    const auto two = run_settings(dir, "two", offset_settings(3, 2));
    ASSERT_EQ(one.rc, 0) << one.log;
    ASSERT_EQ(two.rc, 0) << two.log;
    const std::string text = read_text(one.run / "population.xml");
    EXPECT_EQ(text, read_text(two.run / "population.xml"));
    const auto pop = io::load_population(one.run / "population.xml");
    const std::size_t joints = sim::preset(0, false).actuated().size();
    EXPECT_EQ(pop.offsets, joints);
    std::set<std::vector<double>> distinct;
    for (const auto& ind : pop.population) {
        EXPECT_EQ(ind->direct.size(), joints);
        distinct.insert(ind->direct);
    }
    EXPECT_GT(distinct.size(), 1u);
    fs::remove_all(dir);
}

TEST(OffsetHybrid, ResumeIsExactAndReplaysUseTheOffsets) {
    const auto dir = temp_dir("offset-resume");
    const auto full = run_settings(dir, "full", offset_settings(4, 1));
    ASSERT_EQ(full.rc, 0) << full.log;
    const auto part = run_settings(dir, "part", offset_settings(2, 1));
    ASSERT_EQ(part.rc, 0) << part.log;
    const auto resumed = run_settings(dir, "resumed", offset_settings(4, 2, "<populationXmlLoadFrom>" +
                                                                        (part.run / "population.xml").string() +
                                                                        "</populationXmlLoadFrom>"));
    ASSERT_EQ(resumed.rc, 0) << resumed.log;
    EXPECT_EQ(read_text(resumed.run / "population.xml"), read_text(full.run / "population.xml"));

    // view, trace, assess and render replay through report::replay: the stored fitness, bit for bit,
    const auto items = report::replay(full.run.string(), "best", 3, 0.0, false);
    for (const auto& it : items) EXPECT_EQ(it.replayed_fitness, it.stored_fitness) << it.label;
    // and without the offsets the same trees walk otherwise.
    const auto pop = io::load_population(full.run / "population.xml");
    const auto model = hypergp::Model::from_settings(io::load_settings(full.run / "settings.xml", {}));
    int differ = 0;
    for (const auto& ind : pop.population)
        if (!ind->failed) {
            EXPECT_EQ(hypergp::run(model, ind->genotype, ind->direct).fitness, ind->fitness);
            differ += hypergp::run(model, ind->genotype).fitness != ind->fitness;
        }
    EXPECT_GT(differ, 0);
    fs::remove_all(dir);
}

// A search of trees registered from outside names its checkpoint's root and gives
// its best trees (report::CheckpointBest::trees, with their direct genes in x):
// view, assess, trace and render then replay them as the run's type scores them.
TEST(OffsetHybrid, ARegisteredReaderOfTreesReplaysThemAsTheRunDid) {
    const auto dir = temp_dir("offset-foreign");
    const auto run = run_settings(dir, "run", offset_settings(2, 1));
    ASSERT_EQ(run.rc, 0) << run.log;
    // The "search's own file": a pointer to the population whose best it keeps.
    report::register_checkpoint_reader("treeProbe", [](const io::Settings&, const std::string& file) {
        const std::string text = read_text(file);
        const auto from = text.find("from=\"") + 6;
        const auto pop = io::load_population(text.substr(from, text.find('"', from) - from));
        auto best = *std::max_element(pop.population.begin(), pop.population.end(),
                                      [](const auto& a, const auto& b) { return a->fitness < b->fitness; });
        report::CheckpointBest out;
        out.trees = best->genotype;
        out.x = best->direct;
        out.fitness = best->fitness;
        out.generation = pop.population.generation;
        out.who = "best probed trees";
        return out;
    });
    const fs::path probe = run.run / "probe.xml";
    write_text(probe, "<treeProbe from=\"" + (run.run / "population.xml").string() + "\"/>\n");
    const auto foreign = report::replay(probe.string(), "best", 1, 0.0, true);
    const auto own = report::replay(run.run.string(), "best", 1, 0.0, true);
    ASSERT_EQ(foreign.size(), 1u);
    EXPECT_EQ(foreign[0].replayed_fitness, foreign[0].stored_fitness);
    EXPECT_EQ(foreign[0].replayed_fitness, own[0].replayed_fitness);
    EXPECT_EQ(foreign[0].raw_fitness, own[0].raw_fitness);
    EXPECT_EQ(foreign[0].distance, own[0].distance);
    EXPECT_EQ(foreign[0].raw_outputs, own[0].raw_outputs);
    EXPECT_EQ(foreign[0].duty_factors, own[0].duty_factors);
    EXPECT_NE(foreign[0].label.find("best probed trees"), std::string::npos) << foreign[0].label;
    // One individual is all such a file keeps.
    EXPECT_THROW(report::replay(probe.string(), "3", 1, 0.0, false), InputError);

    // cic export of a run whose saved generations are such files: a row per file, its best.
    const fs::path foreign_run = dir / "foreign-run";
    fs::create_directories(foreign_run / "populations");
    fs::copy_file(run.run / "settings.xml", foreign_run / "settings.xml");
    for (const char* name : {"gen-0000.xml", "gen-0001.xml"}) fs::copy_file(probe, foreign_run / "populations" / name);
    const std::string csv = report::export_individuals({{foreign_run}, true});
    const auto pop = io::load_population(run.run / "population.xml");
    const auto best = *std::max_element(pop.population.begin(), pop.population.end(),
                                        [](const auto& a, const auto& b) { return a->fitness < b->fitness; });
    std::string trees;
    for (const auto& t : best->genotype) trees += (trees.empty() ? "" : " | ") + t.to_string();
    const std::string row = fmt::format(",0,{},{},{},{},{},0,{},,\n", best->fitness, own[0].distance,
                                        own[0].elevation, best->depth(io::load_settings(run.run / "settings.xml", {}).gp.forest_depth), best->size(),
                                        trees);
    EXPECT_NE(csv.find(",0" + row), std::string::npos) << csv;   // generation 0
    EXPECT_NE(csv.find(",1" + row), std::string::npos) << csv;   // generation 1
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3) << csv;

    // What a reader gives is checked against the settings, as cic's own files are.
    report::register_checkpoint_reader("treeProbeWrong", [](const io::Settings&, const std::string& file) {
        const std::string text = read_text(file);
        report::CheckpointBest out;
        if (text.find("gait") != std::string::npos) {
            out.x = {0.5, 0.5};
        } else if (text.find("three") != std::string::npos) {
            out.trees = {tree::Tree::parse("x0"), tree::Tree::parse("x1"), tree::Tree::parse("x2")};
        } else {
            out.trees = {tree::Tree::parse("(add x0 x1)")};
            out.x.assign(text.find("short") != std::string::npos ? 7 : 8, text.find("far") != std::string::npos ? 5.0 : 0.0);
        }
        return out;
    });
    auto refusal = [&](const std::string& what) {
        write_text(probe, "<treeProbeWrong kind=\"" + what + "\"/>\n");
        try {
            (void)report::replay(probe.string(), "best", 1, 0.0, false);
        } catch (const InputError& e) {
            EXPECT_EQ(e.file(), probe.string());
            return e.message();
        }
        return std::string("(accepted)");
    };
    EXPECT_HAS(refusal("short"), "7 offsets, but these settings' Offset-HybrID");
    EXPECT_HAS(refusal("far"), "offset 0 is 5, outside [-2, 2]");
    EXPECT_HAS(refusal("gait"), "gave a gait vector, but Experiment.type hypergp evolves HyperGP trees");
    EXPECT_HAS(refusal("three"), "gave 3 trees, but GP.numberOfTreesInForestGenotype is 1");
    write_text(probe, "<treeProbeWrong kind=\"short\"/>\n");
    fs::copy_file(probe, foreign_run / "populations" / "gen-0000.xml", fs::copy_options::overwrite_existing);
    try {
        (void)report::export_individuals({{foreign_run}, false});
        ADD_FAILURE() << "export took 7 offsets for 8 hinges";
    } catch (const InputError& e) {
        EXPECT_HAS(e.message(), "7 offsets, but these settings' Offset-HybrID");
        EXPECT_EQ(e.file(), (foreign_run / "populations" / "gen-0000.xml").string());
    }
    fs::remove_all(dir);
}

TEST(OffsetHybrid, SettingsAndPopulationsThatDoNotFitAreRefused) {
    const auto dir = temp_dir("offset-refused");
    // Offsets belong to the gait substrate.
    std::string network = offset_settings(2, 1);
    network.replace(network.find("<substrate>gait</substrate>"), std::string("<substrate>gait</substrate>").size(),
                    "");
    const auto r1 = run_settings(dir, "network", network);
    EXPECT_EQ(r1.rc, 2) << r1.log;
    EXPECT_NE(r1.log.find("Neural.directOffsets"), std::string::npos) << r1.log;
    EXPECT_TRUE(r1.run.empty());
    // A population with offsets resumed by settings without them, and the reverse.
    const auto with = run_settings(dir, "with", offset_settings(2, 1));
    ASSERT_EQ(with.rc, 0) << with.log;
    std::string plain = tiny_hypergp_settings(3, 1, "<populationXmlLoadFrom>" + (with.run / "population.xml").string() +
                                                        "</populationXmlLoadFrom>");
    plain.replace(plain.find("</settings>"), 0, "  <Neural><substrate>gait</substrate></Neural>\n");
    const auto r2 = run_settings(dir, "plain", plain);
    EXPECT_EQ(r2.rc, 2) << r2.log;
    EXPECT_NE(r2.log.find("directOffsets"), std::string::npos) << r2.log;   // the origin check names the key
    std::string plain_run = tiny_hypergp_settings(2, 1);
    plain_run.replace(plain_run.find("</settings>"), 0, "  <Neural><substrate>gait</substrate></Neural>\n");
    const auto without = run_settings(dir, "without", plain_run);
    ASSERT_EQ(without.rc, 0) << without.log;
    const auto r3 = run_settings(dir, "again", offset_settings(3, 1, "<populationXmlLoadFrom>" +
                                                                  (without.run / "population.xml").string() +
                                                                  "</populationXmlLoadFrom>"));
    EXPECT_EQ(r3.rc, 2) << r3.log;
    fs::remove_all(dir);
}

} // namespace
} // namespace cic
