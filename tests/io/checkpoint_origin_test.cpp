// Where a checkpoint came from (io/checkpoint_origin.hpp): what is in the
// origin, what is left out, and the one-line refusal naming what differs.
#include <gtest/gtest.h>

#include <string>

#include "cic/core/error.hpp"
#include "cic/io/checkpoint_origin.hpp"
#include "cic/io/population_xml.hpp"

namespace cic::io {
namespace {

Settings gait_on(int robot) {
    Settings s;
    s.experiment.type = "gait";
    s.robot.robot_type = robot;
    return s;
}

std::string refusal(const CheckpointOrigin& made, const Settings& now) {
    try {
        check_origin(made, now, "population.xml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

// The case: a gait checkpoint of R2 resumed as R1 (both gaits can have
// the same parameter count) is refused, naming both robots.
TEST(CheckpointOrigin, AnotherRobotIsRefusedNamingBoth) {
    const CheckpointOrigin r2 = origin_of(gait_on(2));
    const std::string e = refusal(r2, gait_on(1));
    EXPECT_NE(e.find("population.xml: "), std::string::npos) << e;
    EXPECT_NE(e.find("robot: checkpoint R2 ("), std::string::npos) << e;
    EXPECT_NE(e.find(", settings R1 ("), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;   // one line
    EXPECT_EQ(refusal(r2, gait_on(2)), "(no error)");
}

TEST(CheckpointOrigin, TheRobotIsItsGeometryNotItsName) {
    sim::RobotSpec a = sim::preset(1, false), b = a;
    b.name = "renamed";
    EXPECT_NE(robot_origin_text(a), robot_origin_text(b));   // the name is shown...
    b.name = a.name;
    b.modules[1].axis = b.modules[1].axis == sim::Axis::X ? sim::Axis::Z : sim::Axis::X;
    EXPECT_NE(robot_origin_text(a), robot_origin_text(b));   // ...and an axis changes the geometry digest
    b = a;
    b.modules[1].name = "another label";
    EXPECT_EQ(robot_origin_text(a), robot_origin_text(b));   // labels are not geometry
}

TEST(CheckpointOrigin, SimulatorAndControllerKeysAreNamed) {
    Settings made = gait_on(1), now = gait_on(1);
    made.sim.sample_to = 20.0;
    const std::string e = refusal(origin_of(made), now);
    EXPECT_NE(e.find("simulator: sample_to checkpoint 20, settings (default)"), std::string::npos) << e;
    now = gait_on(1);
    now.gait.second_harmonic = true;
    EXPECT_NE(refusal(origin_of(gait_on(1)), now).find("controller: secondHarmonic checkpoint (default), settings 1"),
              std::string::npos)
        << refusal(origin_of(gait_on(1)), now);
}

// Left out: the budget, the seed (a checkpoint holds its own RNG state), keys
// that change no result, and the search's own settings.
TEST(CheckpointOrigin, BudgetSeedWorkersAndSearchSettingsAreLeftOut) {
    const Settings base = gait_on(1);
    Settings other = base;
    other.gait.evaluations = base.gait.evaluations * 3;
    other.experiment.seed = 99;
    other.experiment.workers = 7;
    other.experiment.checkpoint_interval = 5;
    other.control.maximum_iterations = 1000;
    other.gait.sigma0 = 0.1;
    other.gait.population_size = 40;
    EXPECT_EQ(origin_of(other).digest(), origin_of(base).digest());
    Settings gp;   // HyperGP: operator rates and tournament size shape the search, not a stored fitness
    Settings gp2 = gp;
    gp2.gp.tournament_size = 9;
    gp2.gp.mutation_rate = 0.5;
    EXPECT_EQ(origin_of(gp2).digest(), origin_of(gp).digest());
    gp2.gp.primitives.variable_count = 5;
    EXPECT_NE(refusal(origin_of(gp2), gp).find("genotype: terminalVariableCount checkpoint 5, settings 4"), std::string::npos);
    gp2 = gp;
    gp2.neural.substrate = "cpg";
    EXPECT_NE(refusal(origin_of(gp2), gp).find("controller: substrate checkpoint cpg, settings network"),
              std::string::npos)
        << refusal(origin_of(gp2), gp);
}

// A file written before origins (none) is believed, with a note saying so.
TEST(CheckpointOrigin, AFileWithoutAnOriginIsBelievedWithANote) {
    const std::string note = check_origin(std::nullopt, gait_on(1), "old.xml");
    EXPECT_NE(note.find("old.xml has no <origin>"), std::string::npos) << note;
    EXPECT_EQ(check_origin(origin_of(gait_on(1)), gait_on(1), "new.xml"), "");
}

// In a population file: written, read back, and an edit refused.
TEST(CheckpointOrigin, APopulationFileCarriesItAndAnEditIsRefused) {
    Settings s;
    PopulationFile p = describe(s);
    auto ind = std::make_shared<gp::Individual>();
    ind->id = 1;
    ind->genotype = {tree::Tree::parse("(add x0 x1)")};
    p.population.individuals.push_back(ind);
    const std::string text = to_xml(p);
    const PopulationFile back = parse_population(text, "p.xml");
    ASSERT_TRUE(back.origin.has_value());
    EXPECT_EQ(back.origin->parts, p.origin->parts);
    EXPECT_GT(back.origin->line, 0);
    std::string edited = text;
    edited.replace(edited.find("terminalVariableCount=4"), 23, "terminalVariableCount=5");
    try {
        parse_population(edited, "p.xml");
        ADD_FAILURE() << "an edited origin was believed";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("p.xml:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("does not match its parts"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace cic::io
