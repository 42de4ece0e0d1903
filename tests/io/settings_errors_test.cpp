// Every class of bad settings input gets one clear line naming where and what.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "cic/io/settings_io.hpp"
#include "support/expect_has.hpp"

using namespace cic::io;

namespace {

std::string error_of(const std::string& xml) {
    try {
        read_settings_string(xml, "bad.xml");
    } catch (const cic::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

std::string override_error(const std::vector<std::string>& sets) {
    try {
        load_settings({}, sets);
    } catch (const cic::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

std::string gp(const std::string& body) { return "<settings>\n<GP>\n" + body + "\n</GP>\n</settings>\n"; }


} // namespace

TEST(SettingsErrors, MalformedXmlNamesFileAndLine) {
    auto m = error_of("<settings>\n<GP>\n<tournament_size>5</tournament_sizes>\n</GP>\n</settings>\n");
    EXPECT_HAS(m, "bad.xml:3: malformed XML: Opening and ending tag mismatch");
}

TEST(SettingsErrors, UnknownKeySuggestsTheNearest) {
    auto m = error_of(gp("<tournamentSize>5</tournamentSize>"));
    EXPECT_HAS(m, "bad.xml:3: unknown key <GP> tournamentSize; did you mean tournament_size?");
    m = error_of(gp("<populationSize>5</populationSize>"));   // a key of <Gait>, and near one of <GP>
    EXPECT_HAS(m, "'populationSize' belongs in <Gait>, or did you mean generatedPopulationSize?");
    m = error_of(gp("<generatedPopulatonSize>5</generatedPopulatonSize>"));
    EXPECT_HAS(m, "did you mean generatedPopulationSize?");
    m = error_of(gp("<sample_step>0.5</sample_step>"));
    EXPECT_HAS(m, "'sample_step' belongs in <Simulator>");
    m = error_of(gp("<zzzzqqq>1</zzzzqqq>"));
    EXPECT_HAS(m, "cic settings --defaults");
}

TEST(SettingsErrors, UnknownSectionSuggestsTheNearest) {
    auto m = error_of("<settings>\n<Simulater><sample_to>3</sample_to></Simulater>\n</settings>");
    EXPECT_HAS(m, "bad.xml:2: unknown section <Simulater>; did you mean <Simulator>?");
}

TEST(SettingsErrors, WrongTypeNamesSectionKeyValueAndAllowed) {
    auto m = error_of(gp("<generatedPopulationSize>fifty</generatedPopulationSize>"));
    EXPECT_HAS(m, "bad.xml:3: <GP> generatedPopulationSize = \"fifty\": not an integer "
                  "(allowed: integer in [2, 1000000])");
    m = error_of(gp("<generatedPopulationSize>50.5</generatedPopulationSize>"));
    EXPECT_HAS(m, "not a whole number");
    m = error_of(gp("<preventDuplicates>yes</preventDuplicates>"));
    EXPECT_HAS(m, "<GP> preventDuplicates = \"yes\": not a boolean (allowed: 0 or 1)");
    m = error_of(gp("<defaultFitness>nan</defaultFitness>"));
    EXPECT_HAS(m, "not a number");
    m = error_of(gp("<selection_type>best</selection_type>"));
    EXPECT_HAS(m, "allowed: one of: 0|tournament, 1|roulette");
    m = error_of(gp("<functions>add, mul</functions>"));
    EXPECT_HAS(m, "separated by spaces");
    m = error_of(gp("<functions>add mull</functions>"));
    EXPECT_HAS(m, "unknown function 'mull'");
}

TEST(SettingsErrors, OutOfRange) {
    auto m = error_of(gp("<tournament_size>0</tournament_size>"));
    EXPECT_HAS(m, "bad.xml:3: <GP> tournament_size = \"0\": out of range (allowed: integer in [1, 10000000])");
    m = error_of("<settings><Simulator>\n<sample_step>-1</sample_step></Simulator></settings>");
    EXPECT_HAS(m, "bad.xml:2: <Simulator> sample_step = \"-1\": out of range (allowed: number > 0)");
    m = error_of("<settings><Simulator><sample_step>inf</sample_step></Simulator></settings>");
    EXPECT_HAS(m, "infinity is not allowed");
    m = error_of(gp("<generatedPopulationSize>99999999999999999999</generatedPopulationSize>"));
    EXPECT_HAS(m, "out of range");
}

// Issue 39: 1e-400 is not "out of range" for a range that holds it: it underflows.
TEST(SettingsErrors, UnderflowAndOverflowAreCalledSo) {
    auto m = error_of("<settings><Simulator>\n<erp>1e-400</erp></Simulator></settings>");
    EXPECT_HAS(m, "bad.xml:2: <Simulator> erp = \"1e-400\": underflows: it is closer to 0 than a double can hold");
    EXPECT_EQ(m.find("out of range"), std::string::npos) << m;
    m = error_of("<settings><Simulator>\n<erp>1e400</erp></Simulator></settings>");
    EXPECT_HAS(m, "overflows");
}

TEST(SettingsErrors, EmptyValues) {
    auto m = error_of(gp("<tournament_size>  </tournament_size>"));
    EXPECT_HAS(m, "bad.xml:3: <GP> tournament_size = \"\": empty value");
    EXPECT_EQ(error_of(gp("<terminalConsts/>")), "(no error)");   // no constants is meaningful
}

TEST(SettingsErrors, DuplicatesAndNesting) {
    auto m = error_of(gp("<elitism>1</elitism>\n<elitism>2</elitism>"));
    EXPECT_HAS(m, "bad.xml:4: <GP> elitism = \"2\" is given twice, first as \"1\" at line 3");
    // The same value twice is read once (table B.1 lists functionProbabilities twice).
    EXPECT_EQ(error_of(gp("<elitism>1</elitism>\n<elitism> 1 </elitism>")), "(no error)");
    m = error_of(gp("<elitism value=\"1\"/>"));
    EXPECT_HAS(m, "bad.xml:3: <GP> elitism: write the value as the element's text");
    m = error_of("<settings><Simulator><sample_step>0,5</sample_step></Simulator></settings>");
    EXPECT_HAS(m, "the decimal point is '.'");
    m = error_of(gp("<elitism><x/></elitism>"));
    EXPECT_HAS(m, "expected a value, found nested elements");
}

TEST(SettingsErrors, CrossFieldChecksPointAtTheLine) {
    auto m = error_of(gp("<maximumGeneratedTreeDepth>3</maximumGeneratedTreeDepth>\n"
                         "<minimumGeneratedTreeDepth>5</minimumGeneratedTreeDepth>"));
    EXPECT_HAS(m, "bad.xml:4: <GP> minimumGeneratedTreeDepth = \"5\", <GP> maximumGeneratedTreeDepth = \"3\": "
                  "the minimum depth must not exceed the maximum depth");
    m = error_of(gp("<crossoverRate>0.8</crossoverRate><mutationRate>0.3</mutationRate>"));
    EXPECT_HAS(m, "sum to at most 1");
    m = error_of(gp("<generatedPopulationSize>4</generatedPopulationSize>"));
    EXPECT_HAS(m, "tournament cannot be larger than the population");
    m = error_of(gp("<functionCount>3</functionCount><functionProbabilities>1 2</functionProbabilities>"));
    EXPECT_HAS(m, "one weight per function");
    m = error_of(gp("<functionCount>3</functionCount><functions>add mul</functions>"));
    EXPECT_HAS(m, "<GP> functionCount = \"3\" does not match the 2 names in functions");
    m = error_of("<settings><Simulator><delayed_start>20</delayed_start></Simulator></settings>");
    EXPECT_HAS(m, "delayed_start must lie in [sample_from, sample_to)");
    m = error_of(gp("<elitism>50</elitism>"));
    EXPECT_HAS(m, "elitism < population size");
    m = error_of("<settings>\n<Gait>\n<optimizer>sade</optimizer>\n<restarts>ipop</restarts>\n</Gait>\n</settings>\n");
    EXPECT_HAS(m, "bad.xml:4: <Gait> restarts = \"ipop\", <Gait> optimizer = \"sade\": ipop restarts are built for "
                  "cmaes, xnes and sepcmaes only (allowed: Gait.restarts = none | ipop with Gait.optimizer = cmaes | "
                  "xnes | sepcmaes; none with sade)");
    for (const char* optimizer : {"cmaes", "xnes", "sepcmaes"})
        EXPECT_EQ(error_of(std::string("<settings><Gait><optimizer>") + optimizer +
                           "</optimizer><restarts>ipop</restarts></Gait></settings>"),
                  "(no error)")
            << optimizer;
    const auto gait_population = [](const char* optimizer, int size) {
        return std::string("<settings><Experiment><type>gait</type></Experiment><Gait><optimizer>") + optimizer +
               "</optimizer><populationSize>" + std::to_string(size) + "</populationSize></Gait></settings>";
    };
    for (const char* optimizer : {"cmaes", "xnes", "sepcmaes"}) {
        EXPECT_HAS(error_of(gait_population(optimizer, 4)),
                   "cmaes, xnes and sepcmaes need at least 5 candidates per generation, sade 7 (allowed: "
                   "Gait.populationSize = 0 for the optimiser's default, at least 5, or at least 7 with sade)");
        EXPECT_EQ(error_of(gait_population(optimizer, 5)), "(no error)") << optimizer;
    }
    EXPECT_HAS(error_of(gait_population("sade", 6)), "<Gait> populationSize = \"6\", <Gait> optimizer = \"sade\"");
    EXPECT_EQ(error_of(gait_population("sade", 7)), "(no error)");
    m = error_of("<settings><Gait><restarts>bipop</restarts></Gait></settings>");
    EXPECT_HAS(m, "<Gait> restarts = \"bipop\"");
    EXPECT_HAS(m, "allowed: one of: none, ipop");
    m = error_of("<settings><Gait><restartPatience>-1</restartPatience></Gait></settings>");
    EXPECT_HAS(m, "<Gait> restartPatience = \"-1\"");
    m = error_of("<settings><Gait><restartTolerance>-0.5</restartTolerance></Gait></settings>");
    EXPECT_HAS(m, "allowed: number >= 0");
    m = error_of("<settings><Gait><restartTolX>2</restartTolX></Gait></settings>");
    EXPECT_HAS(m, "allowed: number in [0, 1]");
    m = error_of("<settings><Simulator><sample_step>0.5</sample_step></Simulator></settings>");
    EXPECT_HAS(m, "bad.xml:1: <Simulator> sample_step = \"0.5\", <Simulator> extraTimeStepDivider = \"1\": the "
                  "physics step sample_step / extraTimeStepDivider = 0.5 s is above the stability bound 0.025 s");
    EXPECT_HAS(m, "Simulator.allowCoarseStep = 1");
    EXPECT_EQ(error_of("<settings><Simulator><sample_step>0.5</sample_step><extraTimeStepDivider>20"
                       "</extraTimeStepDivider></Simulator></settings>"),
              "(no error)");
    EXPECT_EQ(error_of("<settings><Simulator><sample_step>0.5</sample_step><allowCoarseStep>1"
                       "</allowCoarseStep></Simulator></settings>"),
              "(no error)");
    // The depth cap applies without bloat control, to PTC1's 7 levels at depth 6.
    m = error_of(gp("<maximumTreeDepth>6</maximumTreeDepth>") + "");
    EXPECT_EQ(m, "(no error)");
    m = error_of("<settings><GP><maximumTreeDepth>6</maximumTreeDepth></GP>"
                 "<BloatControl><useBloatControl>0</useBloatControl></BloatControl></settings>");
    EXPECT_HAS(m, "generated trees must fit the depth cap (7 levels");
    m = error_of(gp("<terminalVariableCount>5</terminalVariableCount>"));
    EXPECT_HAS(m, "HyperGP's CPPF has 4 inputs");
    m = error_of("<settings><Control><maximumIterations>0</maximumIterations></Control></settings>");
    EXPECT_HAS(m, "<Control> maximumIterations = \"0\": out of range");
}

TEST(SettingsErrors, OverridesNameTheirSource) {
    EXPECT_HAS(override_error({"GP.tournament_size"}), "--set: expected Section.key=value");
    EXPECT_HAS(override_error({"GP.tournament_size=x"}), "--set: <GP> tournament_size = \"x\": not an integer");
    EXPECT_HAS(override_error({"Gp.elitism=1"}), "--set: unknown section <Gp>; did you mean <GP>?");
    EXPECT_HAS(override_error({"GP.elitsm=1"}), "--set: unknown key <GP> elitsm; did you mean elitism?");
    EXPECT_HAS(override_error({"GP.minimumGeneratedTreeDepth=9"}), "--set: <GP> minimumGeneratedTreeDepth");
}

TEST(SettingsErrors, MissingAndUnreadableFiles) {
    try {
        read_settings("/nonexistent/settings.xml");
        FAIL();
    } catch (const cic::InputError& e) {
        EXPECT_HAS(std::string(e.what()), "/nonexistent/settings.xml: cannot read: No such file or directory");
    }
    auto dir = std::filesystem::temp_directory_path() / ("cic-settings-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "empty.xml") << "";
    EXPECT_THROW(read_settings(dir / "empty.xml"), cic::InputError);
    std::filesystem::remove_all(dir);
}

TEST(SettingsRead, RelativeInputPathsResolveAgainstTheFile) {
    auto dir = std::filesystem::temp_directory_path() / ("cic-settings-rel-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "s.xml") << "<settings><Simulator><robotFile>robots/r.xml</robotFile></Simulator>"
                                    "<Experiment><outputDirectory>out</outputDirectory></Experiment></settings>";
    Settings s = read_settings(dir / "s.xml");
    EXPECT_EQ(s.robot.robot_file, (std::filesystem::absolute(dir) / "robots/r.xml").lexically_normal().string());
    EXPECT_EQ(s.experiment.output_directory, "out");   // outputs stay relative to the current folder
    std::filesystem::remove_all(dir);
}

TEST(SettingsErrors, SubstrateKeysBelongToTheirSubstrate) {
    auto neural = [](const std::string& body) { return "<settings>\n<Neural>\n" + body + "\n</Neural>\n</settings>\n"; };
    auto m = error_of(neural("<evolveClock>1</evolveClock>"));
    EXPECT_HAS(m, "bad.xml:3: <Neural> evolveClock = \"1\", <Neural> clockInputs = \"0\"");
    EXPECT_HAS(m, "an evolved clock needs the network substrate with clock inputs");
    EXPECT_EQ(error_of(neural("<evolveClock>1</evolveClock><clockInputs>1</clockInputs>")), "(no error)");
    m = error_of(neural("<substrate>cpg</substrate>\n<clockInputs>1</clockInputs>"));
    EXPECT_HAS(m, "bad.xml:4: <Neural> clockInputs = \"1\"");
    EXPECT_HAS(m, "clock and bias inputs belong to the network substrate");
    m = error_of(neural("<substrate>gait</substrate><sampleAverageCount>4</sampleAverageCount>"));
    EXPECT_HAS(m, "sample averaging belongs to the network substrate");
    m = error_of(neural("<cpgFeedback>2</cpgFeedback>"));
    EXPECT_HAS(m, "feedback gains belong to the cpg substrate");
    m = error_of(neural("<substrate>oscillator</substrate>"));
    EXPECT_HAS(m, "allowed: one of: network, cpg, gait");
    m = error_of(neural("<frequencyMin>4</frequencyMin>"));
    EXPECT_HAS(m, "<Neural> frequencyMin = \"4\", <Neural> frequencyMax = \"3\": the frequency range is empty");
    m = error_of(neural("<cpgHops>0</cpgHops>"));
    EXPECT_HAS(m, "<Neural> cpgHops = \"0\"");
    EXPECT_EQ(error_of(neural("<substrate>cpg</substrate><cpgFeedback>2</cpgFeedback><cpgHops>3</cpgHops>")),
              "(no error)");
    m = error_of("<settings><Gait><controller>cpg</controller><secondHarmonic>1</secondHarmonic></Gait></settings>");
    EXPECT_HAS(m, "a second harmonic belongs to the sine controller");
    m = error_of("<settings><Gait><controller>neat</controller></Gait></settings>");
    EXPECT_HAS(m, "allowed: one of: sine, cpg");
}
