// Settings read -> write -> read round trips, defaults, thesis keys and name/count forms.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "cic/io/settings_io.hpp"
#include "cic/io/settings_table.hpp"

using namespace cic::io;

namespace {

// The thesis's Appendix B keys, each under its section.
const std::vector<std::pair<std::string, std::string>> kThesisKeys = {
    {"GP", "defaultFitness"}, {"GP", "generatedPopulationSize"}, {"GP", "expectedGeneratedTreeSize"},
    {"GP", "maximumGeneratedTreeDepth"}, {"GP", "minimumGeneratedTreeDepth"}, {"GP", "terminalVariableCount"},
    {"GP", "functionCount"}, {"GP", "functionProbabilities"}, {"GP", "terminalConstsCount"},
    {"GP", "tournament_size"}, {"GP", "selection_type"}, {"GP", "tournamentSelection"},
    {"GP", "numberOfTreesInForestGenotype"}, {"GP", "preventDuplicates"},
    {"Simulator", "sample_from"}, {"Simulator", "sample_step"}, {"Simulator", "sample_to"},
    {"Simulator", "delayed_start"}, {"Simulator", "robot_type"}, {"Simulator", "extraTimeStepDivider"},
    {"Simulator", "generatePovrayFiles"},
    {"Control", "maximumIterations"}, {"Control", "minimumFitness"}, {"Control", "populationXmlLoadFrom"},
    {"Control", "useMatlabPlot"}, {"Control", "isAutonomousExperiment"},
    {"BloatControl", "useBloatControl"}, {"BloatControl", "bloatControlVariant"},
    {"Neural", "synopsisThreshold"}, {"Neural", "useMiddleLegs"}, {"Neural", "sampleAverageCount"}};

// A thesis-style file with non-default values for every Appendix B key.
const char* kThesisFile = R"(<?xml version="1.0"?>
<settings>
  <GP>
    <defaultFitness>-2.5</defaultFitness>
    <generatedPopulationSize>60</generatedPopulationSize>
    <expectedGeneratedTreeSize>25</expectedGeneratedTreeSize>
    <maximumGeneratedTreeDepth>7</maximumGeneratedTreeDepth>
    <minimumGeneratedTreeDepth>3</minimumGeneratedTreeDepth>
    <terminalVariableCount>3</terminalVariableCount>
    <functionCount>4</functionCount>
    <functionProbabilities>1 2 3 4</functionProbabilities>
    <terminalConstsCount>3</terminalConstsCount>
    <tournament_size>6</tournament_size>
    <selection_type>1</selection_type>
    <tournamentSelection>0</tournamentSelection>
    <numberOfTreesInForestGenotype>4</numberOfTreesInForestGenotype>
    <preventDuplicates>0</preventDuplicates>
  </GP>
  <Simulator>
    <sample_from>0.5</sample_from>
    <sample_step>0.5</sample_step>
    <sample_to>12</sample_to>
    <delayed_start>1.5</delayed_start>
    <robot_type>2</robot_type>
    <extraTimeStepDivider>20</extraTimeStepDivider>
    <generatePovrayFiles>1</generatePovrayFiles>
  </Simulator>
  <Control>
    <maximumIterations>77</maximumIterations>
    <minimumFitness>12.25</minimumFitness>
    <populationXmlLoadFrom>/tmp/pop.xml</populationXmlLoadFrom>
    <useMatlabPlot>1</useMatlabPlot>
    <isAutonomousExperiment>0</isAutonomousExperiment>
  </Control>
  <BloatControl>
    <useBloatControl>0</useBloatControl>
    <bloatControlVariant>2</bloatControlVariant>
  </BloatControl>
  <Neural>
    <synopsisThreshold>0.3</synopsisThreshold>
    <useMiddleLegs>1</useMiddleLegs>
    <sampleAverageCount>4</sampleAverageCount>
  </Neural>
</settings>
)";

} // namespace

TEST(SettingsTable, EveryThesisKeyIsInTheTable) {
    for (const auto& [section, key] : kThesisKeys)
        EXPECT_NE(find_setting(section, key), nullptr) << section << "." << key;
}

TEST(SettingsTable, KeysAreUniqueAndDocumented) {
    std::set<std::string> seen;
    for (const auto& k : settings_table()) {
        EXPECT_TRUE(seen.insert(k.section + "." + k.key).second) << k.key;
        EXPECT_FALSE(k.doc.empty()) << k.key;
        EXPECT_FALSE(describe_allowed(k).empty()) << k.key;
        EXPECT_NO_THROW(default_text(k)) << k.key;
    }
}

TEST(SettingsRead, ThesisFileLoadsWithItsValues) {
    Settings s = read_settings_string(kThesisFile, "thesis.xml");
    EXPECT_EQ(s.gp.default_fitness, -2.5);
    EXPECT_EQ(s.gp.population_size, 60);
    EXPECT_EQ(s.gp.primitives.functions.size(), 4u);
    EXPECT_EQ(s.gp.primitives.functions[0], cic::tree::Op::Add);   // first N of the canonical list
    EXPECT_EQ(s.gp.primitives.function_weights, (std::vector<double>{1, 2, 3, 4}));
    EXPECT_EQ(s.gp.primitives.constants, (std::vector<double>{1.0, -1.0, 0.0}));
    EXPECT_EQ(s.gp.selection, cic::gp::SelectionType::Roulette);
    EXPECT_FALSE(s.gp.lexicographic_parsimony);
    EXPECT_EQ(s.gp.trees_per_genotype, 4);
    EXPECT_EQ(s.sim.sample_step, 0.5);
    EXPECT_EQ(s.sim.step_divider, 20);
    EXPECT_EQ(s.robot.robot_type, 2);
    EXPECT_TRUE(s.robot.generate_povray);
    EXPECT_EQ(s.control.maximum_iterations, 77);
    EXPECT_EQ(s.control.population_load_from, "/tmp/pop.xml");
    EXPECT_TRUE(s.control.plot);
    EXPECT_FALSE(s.control.autonomous);
    EXPECT_FALSE(s.bloat.enabled);
    EXPECT_EQ(s.bloat.variant, cic::gp::BloatVariant::VeryHeavy);
    EXPECT_EQ(s.neural.threshold, 0.3);
    EXPECT_TRUE(s.neural.middle_legs);
    EXPECT_EQ(s.neural.sample_average_count, 4);
}

TEST(SettingsRead, EveryThesisKeyRoundTrips) {
    Settings a = read_settings_string(kThesisFile, "thesis.xml");
    std::string text = write_settings(a);
    Settings b = read_settings_string(text, "written.xml");
    for (const auto& k : settings_table()) EXPECT_EQ(k.get(a), k.get(b)) << k.section << "." << k.key;
    EXPECT_EQ(write_settings(b), text);
    // Each thesis key changed from its default shows up changed after the round trip.
    for (const auto& [section, key] : kThesisKeys) {
        const auto* k = find_setting(section, key);
        if (key == "functionProbabilities" || key == "functionCount" || key == "terminalConstsCount") continue;
        EXPECT_NE(k->get(b), default_text(*k)) << key << " kept its default; the test file should change it";
    }
}

TEST(SettingsRead, EveryKeyRoundTripsThroughOverrides) {
    // Write a non-default value through --set for each key type, write, read back.
    Settings a = load_settings({}, {"GP.functions=sub div cos", "GP.terminalConsts=0.5 -3 1e-07",
                                    "Simulator.friction=inf", "Experiment.seed=18446744073709551615",
                                    "Neural.synapseTypes=ih oo", "Neural.forestMap=0 1 0 1 0",
                                    "GP.numberOfTreesInForestGenotype=2", "Neural.neuronModel=integrating",
                                    "GP.initMethod=rhh", "Control.minimumFitness=-inf",
                                    "SymbolicRegression.target=x0*x0", "Experiment.type=hypergp"});
    EXPECT_TRUE(std::isinf(a.sim.friction));
    EXPECT_EQ(a.gp.primitives.function_weights.size(), 3u);   // reset to one weight per function
    Settings b = read_settings_string(write_settings(a), "w.xml");
    for (const auto& k : settings_table()) EXPECT_EQ(k.get(a), k.get(b)) << k.key;
    EXPECT_EQ(b.experiment.seed, 18446744073709551615ull);
    EXPECT_EQ(b.gp.primitives.constants, (std::vector<double>{0.5, -3, 1e-07}));
    EXPECT_EQ(b.neural.synapse_enabled, (std::vector<bool>{true, false, false, true, false}));
}

TEST(SettingsRead, DefaultsFileParsesBackToDefaults) {
    const Settings defaults;
    std::string documented = write_settings(defaults, true);
    EXPECT_NE(documented.find("<!--"), std::string::npos);
    Settings back = read_settings_string(documented, "defaults.xml");
    for (const auto& k : settings_table()) EXPECT_EQ(k.get(back), default_text(k)) << k.key;
    EXPECT_EQ(read_settings_string("<settings/>").gp.population_size, defaults.gp.population_size);
}

TEST(SettingsRead, NamesAndThesisCountsAgree) {
    Settings s = read_settings_string(
        "<settings><GP><functions>add mul atan</functions><functionCount>3</functionCount>"
        "<terminalConsts>1 -1</terminalConsts><terminalConstsCount>2</terminalConstsCount>"
        "<functionProbabilities>2</functionProbabilities></GP></settings>");
    EXPECT_EQ(s.gp.primitives.function_weights, (std::vector<double>{2, 2, 2}));
    EXPECT_EQ(s.gp.primitives.constants, (std::vector<double>{1, -1}));
    // A shorter function set given alone gets equal weights.
    Settings t = read_settings_string("<settings><GP><functionCount>2</functionCount></GP></settings>");
    EXPECT_EQ(t.gp.primitives.function_weights, (std::vector<double>{1, 1}));
    // Aliases: names for numeric thesis enums.
    Settings u = read_settings_string(
        "<settings><GP><selection_type>roulette</selection_type></GP>"
        "<BloatControl><bloatControlVariant>heavy</bloatControlVariant></BloatControl></settings>");
    EXPECT_EQ(u.gp.selection, cic::gp::SelectionType::Roulette);
    EXPECT_EQ(u.bloat.variant, cic::gp::BloatVariant::Heavy);
    EXPECT_EQ(find_setting("GP", "selection_type")->get(u), "1");   // written in the thesis form
}

TEST(SettingsRead, LaterOverrideWins) {
    Settings s = load_settings({}, {"GP.tournament_size=3", "GP.tournament_size=4"});
    EXPECT_EQ(s.gp.tournament_size, 4);
}
