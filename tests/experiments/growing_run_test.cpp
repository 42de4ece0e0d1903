// Evolving for transfer end to end through the real binary (the generational
// search's growing robot, src/search/generational.cpp; several bodies,
// experiments/hypergp/bodies.cpp): a growing run moves to its next body at its
// share of the budget, re-evaluating the population there; resumed from the
// checkpoint just before or just after the change it ends in the same bytes;
// 1 and 2 workers agree; and what the settings cannot do is refused before a
// folder exists.
#include <gtest/gtest.h>

#include <string>

#include "cic/io/population_xml.hpp"
#include "support/expect_has.hpp"
#include "support/run_helpers.hpp"

namespace cic {
namespace {

using namespace cic::testing;
namespace fs = std::filesystem;
const std::string kRobots = (fs::path(CIC_SOURCE_DIR) / "settings" / "robots").string();

// HyperGP-gait on centipede-2, population 6, 2.5 s walks, 4 generations; the
// extra Simulator keys and Control keys given.
std::string settings(int workers, const std::string& simulator, const std::string& control = "") {
    return R"(<?xml version="1.0"?>
<settings>
  <Experiment><type>hypergp</type><seed>7</seed><workers>)" + std::to_string(workers) + R"(</workers></Experiment>
  <GP><generatedPopulationSize>6</generatedPopulationSize><tournament_size>3</tournament_size>
      <expectedGeneratedTreeSize>10</expectedGeneratedTreeSize><maximumGeneratedTreeDepth>4</maximumGeneratedTreeDepth>
      <numberOfTreesInForestGenotype>3</numberOfTreesInForestGenotype><elitism>1</elitism></GP>
  <Simulator><robotFile>)" + kRobots + R"(/centipede-2.xml</robotFile><sample_to>2.5</sample_to>
      <delayed_start>0.5</delayed_start><collisionSpace>1</collisionSpace>)" + simulator + R"(</Simulator>
  <Control><maximumIterations>4</maximumIterations>)" + control + R"(</Control>
  <Neural><substrate>gait</substrate><frequencyMax>3</frequencyMax></Neural>
</settings>
)";
}

const std::string kGrow = "<growRobotFiles>" + kRobots + "/centipede-4.xml</growRobotFiles><growAt>0.5</growAt>";

TEST(GrowingRun, MovesAtItsShareAndResumesExactlyAcrossTheChange) {
    const auto dir = temp_dir("grow-run");
    const auto full = run_settings(dir, "full", settings(1, kGrow));
    ASSERT_EQ(full.rc, 0) << full.log;
    // Body 1 from generation ceil(0.5 x 4) = 2, which is the population of
    // generation 1 evaluated again there: 6 more evaluations, no breeding.
    const auto before = io::load_population(full.run / "populations" / "gen-0001.xml");
    const auto after = io::load_population(full.run / "populations" / "gen-0002.xml");
    ASSERT_TRUE(before.body && after.body);
    EXPECT_EQ(*before.body, 0u);
    EXPECT_EQ(*after.body, 1u);
    EXPECT_EQ(after.state.evaluations, before.state.evaluations + 6);
    ASSERT_EQ(after.population.size(), before.population.size());
    for (std::size_t i = 0; i < after.population.size(); ++i) {
        EXPECT_EQ(after.population[i].id, before.population[i].id);
        EXPECT_EQ(after.population[i].genotype, before.population[i].genotype);
    }
    EXPECT_EQ(before.state.rng.state_text(), after.state.rng.state_text());   // the change draws no random number
    EXPECT_HAS(read_text(full.run / "run.log"), "generation 2: the robot grows to body 1");
    EXPECT_HAS(read_text(full.run / "summary.txt"), "robot centipede-4");
    EXPECT_HAS(read_text(full.run / "population.xml"), "<body index=\"1\"/>");

    // A stop just before the change and just after it: the same bytes, with 2 workers.
    for (const char* from : {"gen-0001.xml", "gen-0002.xml"}) {
        const auto resumed = run_settings(dir, std::string("from-") + from,
                                          settings(2, kGrow, "<populationXmlLoadFrom>" +
                                                                 (full.run / "populations" / from).string() +
                                                                 "</populationXmlLoadFrom>"));
        ASSERT_EQ(resumed.rc, 0) << resumed.log;
        EXPECT_EQ(read_text(resumed.run / "population.xml"), read_text(full.run / "population.xml")) << from;
    }
    // Another schedule refuses the checkpoint, naming the growth.
    const auto other = run_settings(dir, "other",
                                    settings(1, "<growRobotFiles>" + kRobots +
                                                    "/centipede-4.xml</growRobotFiles><growAt>0.75</growAt>",
                                             "<populationXmlLoadFrom>" +
                                                 (full.run / "populations" / "gen-0001.xml").string() +
                                                 "</populationXmlLoadFrom>"));
    EXPECT_EQ(other.rc, 2) << other.log;
    EXPECT_HAS(other.log, "growth: checkpoint at 0.5");
    fs::remove_all(dir);
}

TEST(GrowingRun, SeveralBodiesGiveTheSameRunWithOneOrTwoWorkers) {
    const auto dir = temp_dir("bodies-run");
    const std::string extra = "<extraRobotFiles>" + kRobots + "/centipede-4.xml</extraRobotFiles>"
                              "<bodiesAggregate>min</bodiesAggregate>";
    const auto one = run_settings(dir, "one", settings(1, extra));
    const auto two = run_settings(dir, "two", settings(2, extra));
    ASSERT_EQ(one.rc, 0) << one.log;
    ASSERT_EQ(two.rc, 0) << two.log;
    EXPECT_EQ(read_text(one.run / "population.xml"), read_text(two.run / "population.xml"));
    EXPECT_HAS(read_text(one.run / "summary.txt"), "and centipede-4 (minimum of the bodies' fitnesses)");
    EXPECT_EQ(read_text(one.run / "population.xml").find("<body"), std::string::npos);
    fs::remove_all(dir);
}

TEST(GrowingRun, UnsupportedCombinationsAreRefusedBeforeAnythingIsWritten) {
    const auto dir = temp_dir("bodies-refused");
    std::string text = settings(1, "<extraRobotFiles>" + kRobots + "/centipede-4.xml</extraRobotFiles>");
    text.replace(text.find("</settings>"), 0, "<MapElites><enabled>1</enabled></MapElites>");
    const auto refused = run_settings(dir, "refused", text);
    EXPECT_EQ(refused.rc, 2) << refused.log;
    EXPECT_HAS(refused.log, "<Simulator> extraRobotFiles");
    EXPECT_FALSE(fs::exists(dir / "refused"));
    const auto missing = run_settings(dir, "missing", settings(1, "<extraRobotFiles>no-such-robot.xml</extraRobotFiles>"));
    EXPECT_EQ(missing.rc, 2) << missing.log;
    EXPECT_HAS(missing.log, "extraRobotFiles");
    EXPECT_FALSE(fs::exists(dir / "missing"));
    fs::remove_all(dir);
}

} // namespace
} // namespace cic
