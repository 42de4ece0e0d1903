// HyperGP end to end through the real binary: a tiny run writes its files,
// 1 and 2 workers agree bit for bit, a resume is exact, the best never falls,
// and a replay reproduces the stored fitness.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <map>

#include <sys/wait.h>
#include <unistd.h>

#include "cic/report/replay.hpp"
#include "cic/core/error.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/stats_csv.hpp"
#include "support/run_helpers.hpp"

namespace cic {
namespace {

using namespace cic::testing;
namespace fs = std::filesystem;

TEST(HypergpRun, TinyRunWritesPopulationStatsAndCheckpoints) {
    const auto dir = temp_dir("hgp-files");
    const auto r = run_settings(dir, "a", tiny_hypergp_settings(3, 1));
    ASSERT_EQ(r.rc, 0) << r.log;
    EXPECT_TRUE(fs::exists(r.run / "settings.xml"));
    EXPECT_TRUE(fs::exists(r.run / "population.xml"));
    EXPECT_TRUE(fs::exists(r.run / "populations" / "gen-0000.xml"));
    EXPECT_TRUE(fs::exists(r.run / "populations" / "gen-0002.xml"));
    const std::string stats = read_text(r.run / "stats.csv");
    EXPECT_EQ(stats.rfind(io::kStatsColumns, 0), 0u) << stats;
    EXPECT_EQ(std::count(stats.begin(), stats.end(), '\n'), 4) << stats;   // header + 3 generations
    const auto pop = io::load_population(r.run / "population.xml");
    EXPECT_EQ(pop.population.size(), 6u);
    EXPECT_EQ(pop.population.generation, 2);
    fs::remove_all(dir);
}

// A genotype met again reuses its result: with tiny trees and no duplicate
// prevention many repeat, run.log counts them, and every repeated genotype in
// the population has the fitness bits of its first evaluation.
TEST(HypergpRun, RepeatedGenotypesReuseTheirResult) {
    const auto dir = temp_dir("hgp-reuse");
    std::string text = tiny_hypergp_settings(8, 2);
    text.replace(text.find("<elitism>1</elitism>"), 0,
                 "<preventDuplicates>0</preventDuplicates><maximumGeneratedTreeDepth>1</maximumGeneratedTreeDepth>"
                 "<minimumGeneratedTreeDepth>1</minimumGeneratedTreeDepth><maximumMutationDepth>1</maximumMutationDepth>"
                 "<crossoverRate>0.2</crossoverRate><mutationRate>0.8</mutationRate>");
    text.erase(text.find("<maximumGeneratedTreeDepth>4</maximumGeneratedTreeDepth>"),
               std::string("<maximumGeneratedTreeDepth>4</maximumGeneratedTreeDepth>").size());
    const auto r = run_settings(dir, "a", text);
    ASSERT_EQ(r.rc, 0) << r.log;
    const std::string log = read_text(r.run / "run.log");
    const auto at = log.find("evaluations this session: ");
    ASSERT_NE(at, std::string::npos) << log;
    long simulated = 0, reused = 0;
    ASSERT_EQ(std::sscanf(log.c_str() + at, "evaluations this session: %ld simulated, %ld reused", &simulated, &reused), 2);
    EXPECT_GT(reused, 0) << log.substr(at);
    const auto pop = io::load_population(r.run / "population.xml");
    EXPECT_EQ(simulated + reused, pop.state.evaluations);
    std::map<std::string, double> fitness_of;
    for (const auto& ind : pop.population) {
        std::string key;
        for (const auto& t : ind->genotype) key += t.to_string() + "|";
        const auto [it, fresh] = fitness_of.emplace(key, ind->fitness);
        if (!fresh) {
            EXPECT_EQ(std::bit_cast<std::uint64_t>(it->second), std::bit_cast<std::uint64_t>(ind->fitness)) << key;
        }
    }
    fs::remove_all(dir);
}

TEST(HypergpRun, OneAndTwoWorkersGiveIdenticalPopulations) {
    const auto dir = temp_dir("hgp-workers");
    const auto one = run_settings(dir, "one", tiny_hypergp_settings(3, 1));
    const auto two = run_settings(dir, "two", tiny_hypergp_settings(3, 2));
    ASSERT_EQ(one.rc, 0) << one.log;
    ASSERT_EQ(two.rc, 0) << two.log;
    EXPECT_EQ(read_text(one.run / "population.xml"), read_text(two.run / "population.xml"));
    fs::remove_all(dir);
}

TEST(HypergpRun, ResumeIsExactAndBestNeverFalls) {
    const auto dir = temp_dir("hgp-resume");
    const auto full = run_settings(dir, "full", tiny_hypergp_settings(4, 1));
    ASSERT_EQ(full.rc, 0) << full.log;
    const auto part = run_settings(dir, "part", tiny_hypergp_settings(2, 1));
    ASSERT_EQ(part.rc, 0) << part.log;
    const auto resumed = run_settings(dir, "resumed", tiny_hypergp_settings(4, 2, "<populationXmlLoadFrom>" +
                                                                     (part.run / "population.xml").string() +
                                                                     "</populationXmlLoadFrom>"));
    ASSERT_EQ(resumed.rc, 0) << resumed.log;
    EXPECT_EQ(read_text(resumed.run / "population.xml"), read_text(full.run / "population.xml"));

    // Elitism 1: the best fitness never falls from one generation to the next.
    std::istringstream stats(read_text(full.run / "stats.csv"));
    std::string line;
    std::getline(stats, line);
    double previous = -1e300;
    while (std::getline(stats, line)) {
        const auto c1 = line.find(',');
        const double best = std::stod(line.substr(c1 + 1));
        EXPECT_GE(best, previous) << line;
        previous = best;
    }
    fs::remove_all(dir);
}

TEST(HypergpRun, ReplayReproducesTheStoredFitness) {
    const auto dir = temp_dir("hgp-replay");
    const auto r = run_settings(dir, "a", tiny_hypergp_settings(2, 1));
    ASSERT_EQ(r.rc, 0) << r.log;
    const auto items = report::replay(r.run.string(), "best", 3, 10.0, true);
    ASSERT_EQ(items.size(), 3u);
    for (const auto& it : items) {
        EXPECT_EQ(it.replayed_fitness, it.stored_fitness) << it.label;   // bit for bit
        EXPECT_FALSE(it.recording.frames.empty());
        EXPECT_FALSE(it.trace.empty());
        EXPECT_EQ(it.raw_outputs.size(), it.trace.size());
    }
    EXPECT_GE(items[0].stored_fitness, items[1].stored_fitness);
    EXPECT_THROW(report::replay(r.run.string(), "123456789", 1, 10.0, false), InputError);
    EXPECT_THROW(report::replay((dir / "nope").string(), "best", 1, 10.0, false), InputError);
    fs::remove_all(dir);
}

// The CPG and gait substrates and the evolved clock replay (view, trace, assess
// and render all go through report::replay) to their stored fitness, bit for bit.
TEST(HypergpRun, EverySubstrateReplaysItsStoredFitness) {
    const auto dir = temp_dir("hgp-substrates");
    const std::vector<std::string> neural = {
        "<substrate>cpg</substrate><cpgFeedback>1.5</cpgFeedback>",
        "<substrate>gait</substrate>",
        "<clockInputs>1</clockInputs><evolveClock>1</evolveClock>",
        "<clockInputs>1</clockInputs><oscillationPenalty>frequency</oscillationPenalty>"
        "<penaltyMaxFrequency>0.1</penaltyMaxFrequency>"};
    for (std::size_t i = 0; i < neural.size(); ++i) {
        std::string text = tiny_hypergp_settings(2, 1);
        text.replace(text.find("</settings>"), 0, "  <Neural>" + neural[i] + "</Neural>\n");
        const auto r = run_settings(dir, "s" + std::to_string(i), text);
        ASSERT_EQ(r.rc, 0) << r.log;
        const auto items = report::replay(r.run.string(), "best", 2, 10.0, true);
        ASSERT_EQ(items.size(), 2u);
        for (const auto& it : items) {
            EXPECT_EQ(it.replayed_fitness, it.stored_fitness) << neural[i] << ": " << it.label;
            EXPECT_FALSE(it.trace.empty());
            EXPECT_EQ(it.raw_outputs.size(), it.trace.size());
            // raw_fitness is eq. 7.1 without the penalty, the score every method is compared on.
            if (i < 3) {
                EXPECT_EQ(it.raw_fitness, it.replayed_fitness);
            } else if (it.replayed_fitness >= 0) {
                EXPECT_GE(it.raw_fitness, it.replayed_fitness);
            }
        }
    }
    fs::remove_all(dir);
}

// A timeout too short for any evaluation: every job is retried on a fresh
// worker, then scored as failed. Each step leaves a warning in run.log, and
// stats.csv counts the failures.
TEST(HypergpRun, TroubleWithWorkersIsReported) {
    const auto dir = temp_dir("hgp-trouble");
    std::string text = tiny_hypergp_settings(2, 2);
    text.replace(text.find("</Experiment>"), 0, "<workerTimeout>0.000001</workerTimeout>");
    const auto r = run_settings(dir, "a", text);
    ASSERT_EQ(r.rc, 0) << r.log;
    const std::string log = read_text(r.run / "run.log");
    EXPECT_NE(log.find("job timed out after 0.000001 s; worker replaced, job retried"), std::string::npos) << log;
    EXPECT_NE(log.find("scored as failed (fitness -1000): job timed out"), std::string::npos) << log;
    EXPECT_NE(r.log.find("scored as failed"), std::string::npos) << "warnings reach the console even with --quiet";
    std::istringstream stats(read_text(r.run / "stats.csv"));
    std::string header, row;
    std::getline(stats, header);
    std::getline(stats, row);
    ASSERT_EQ(header.substr(header.rfind(',') + 1), "failed");
    EXPECT_GT(std::stoi(row.substr(row.rfind(',') + 1)), 0) << row;
    fs::remove_all(dir);
}

} // namespace
} // namespace cic