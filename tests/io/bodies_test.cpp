// Evolving for transfer's settings (src/io/bodies.cpp and the table's rows):
// the growing robot's schedule, the keys' checks, their paths, their round
// trip, and that at their defaults they leave a run's digest and origin alone.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "cic/io/bodies.hpp"
#include "cic/io/checkpoint_origin.hpp"
#include "cic/io/population_xml.hpp"   // settings_digest
#include "cic/io/settings_io.hpp"
#include "cic/io/settings_table.hpp"
#include "support/expect_has.hpp"
#include "support/input_error.hpp"

namespace cic::io {
namespace {

namespace fs = std::filesystem;
using cic::testing::input_error;
const std::string kRobots = (fs::path(CIC_SOURCE_DIR) / "settings" / "robots").string();

Settings with(const std::vector<std::string>& sets) { return load_settings_text("<settings/>", "t.xml", sets); }

TEST(Bodies, TheScheduleStartsEachBodyAtItsShareOfTheBudget) {
    Settings s;
    s.control.maximum_iterations = 50;
    s.robot.grow_robot_files = {"a.xml", "b.xml"};
    s.robot.grow_at = {0.25, 0.5};
    EXPECT_TRUE(grows(s));
    EXPECT_EQ(growing_bodies(s), 3u);
    EXPECT_EQ(grow_generation(s, 1), 13);   // ceil(12.5)
    EXPECT_EQ(grow_generation(s, 2), 25);
    EXPECT_EQ(body_of_generation(s, 0), 0u);
    EXPECT_EQ(body_of_generation(s, 12), 0u);
    EXPECT_EQ(body_of_generation(s, 13), 1u);
    EXPECT_EQ(body_of_generation(s, 24), 1u);
    EXPECT_EQ(body_of_generation(s, 25), 2u);
    EXPECT_EQ(body_of_generation(s, 49), 2u);
    EXPECT_THROW((void)grow_generation(s, 0), std::out_of_range);
    EXPECT_THROW((void)grow_generation(s, 3), std::out_of_range);
    s.control.maximum_iterations = 10;
    s.robot.grow_at = {0.7, 0.9};   // 0.7 * 10 is 7.000000000000001 in doubles
    EXPECT_EQ(grow_generation(s, 1), 7);
    EXPECT_EQ(grow_generation(s, 2), 9);
    EXPECT_EQ(body_of_generation(Settings{}, 1000), 0u);
    EXPECT_FALSE(grows(Settings{}));
    EXPECT_FALSE(several_bodies(Settings{}));
}

TEST(Bodies, RefusedCombinationsNameTheirKeys) {
    const std::string c4 = kRobots + "/centipede-4.xml";
    EXPECT_HAS(input_error([&] { with({"Simulator.extraRobotFiles=" + c4, "MapElites.enabled=1"}); }),
               "<Simulator> extraRobotFiles");
    EXPECT_HAS(input_error([&] { with({"Simulator.extraRobotFiles=" + c4, "MapElites.enabled=1"}); }),
               "MapElites.enabled = 0");
    EXPECT_HAS(input_error([&] { with({"Simulator.growRobotFiles=" + c4, "Simulator.growAt=0.5", "Experiment.type=gait"}); }),
               "<Simulator> growRobotFiles");
    EXPECT_HAS(input_error([&] { with({"Simulator.extraRobotFiles=" + c4, "Neural.substrate=gait",
                                       "Neural.switchPatience=5"}); }),
               "Switch-HybrID");
    EXPECT_HAS(input_error([&] { with({"Simulator.growRobotFiles=" + c4, "Simulator.growAt=0.5", "Neural.substrate=gait",
                                       "Neural.directOffsets=1"}); }),
               "Neural.directOffsets = 0");
    EXPECT_HAS(input_error([&] { with({"Simulator.extraRobotFiles=" + c4, "Experiment.search=map-elites"}); }),
               "Experiment.search = auto | generational");
    EXPECT_HAS(input_error([&] { with({"Simulator.extraRobotFiles=" + c4, "Simulator.growRobotFiles=" + c4,
                                       "Simulator.growAt=0.5"}); }),
               "do not combine");
    EXPECT_HAS(input_error([&] { with({"Simulator.growRobotFiles=" + c4}); }), "one share of the budget per body");
    EXPECT_HAS(input_error([&] { with({"Simulator.growRobotFiles=" + c4 + " " + c4, "Simulator.growAt=0.5 0.4"}); }),
               "each body needs a generation of its own");
    EXPECT_HAS(input_error([&] { with({"Simulator.growRobotFiles=" + c4, "Simulator.growAt=0.999"}); }),
               "before the last generation");
    EXPECT_HAS(input_error([&] { with({"Simulator.growAt=1.5"}); }), "<Simulator> growAt");
    EXPECT_HAS(input_error([&] { with({"Simulator.bodiesAggregate=median"}); }), "mean");
    EXPECT_HAS(input_error([&] { with({"Neural.substrateLayout=square"}); }), "normalised");
    EXPECT_HAS(input_error([&] { with({"Neural.substrateUnit=0"}); }), "<Neural> substrateUnit");
    // Allowed: the generational HyperGP search.
    const Settings s = with({"Simulator.growRobotFiles=" + c4, "Simulator.growAt=0.5"});
    EXPECT_EQ(grow_generation(s, 1), 25);
}

TEST(Bodies, PathListsResolveAgainstTheFileAndRoundTrip) {
    const fs::path dir = fs::temp_directory_path() / ("cic-bodies-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "s.xml") << "<settings><Simulator><extraRobotFiles>robots/a.xml /abs/b.xml</extraRobotFiles>"
                                    "<bodiesAggregate>min</bodiesAggregate></Simulator>"
                                    "<Neural><substrateLayout>absolute</substrateLayout><substrateUnit>4</substrateUnit>"
                                    "</Neural></settings>";
    const Settings s = read_settings(dir / "s.xml");
    ASSERT_EQ(s.robot.extra_robot_files.size(), 2u);
    EXPECT_EQ(s.robot.extra_robot_files[0], (fs::absolute(dir) / "robots/a.xml").lexically_normal().string());
    EXPECT_EQ(s.robot.extra_robot_files[1], "/abs/b.xml");
    EXPECT_EQ(s.robot.bodies_aggregate, BodiesAggregate::Min);
    EXPECT_EQ(s.neural.substrate_layout, nn::SubstrateLayout::Absolute);
    EXPECT_EQ(s.neural.substrate_unit, 4.0);
    const Settings again = read_settings_string(write_settings(s), "again.xml");
    EXPECT_EQ(write_settings(again), write_settings(s));
    EXPECT_EQ(again.robot.extra_robot_files, s.robot.extra_robot_files);
    EXPECT_EQ(settings_digest(again), settings_digest(s));
    fs::remove_all(dir);
}

// New keys at their defaults change neither the settings digest nor the
// checkpoint origin; given, they change both, and the origin names every body.
TEST(Bodies, DefaultsLeaveDigestAndOriginAlone) {
    for (const char* key : {"Simulator.extraRobotFiles", "Simulator.bodiesAggregate", "Simulator.growRobotFiles",
                            "Simulator.growAt", "Neural.substrateLayout", "Neural.substrateUnit"}) {
        const std::string k(key);
        const SettingKey* row = find_setting(k.substr(0, k.find('.')), k.substr(k.find('.') + 1));
        ASSERT_NE(row, nullptr) << key;
        EXPECT_FALSE(row->digest_at_default) << key;
    }
    const Settings plain = with({});
    const Settings same = with({"Simulator.bodiesAggregate=mean", "Neural.substrateLayout=normalised"});
    EXPECT_EQ(settings_digest(plain), settings_digest(same));
    EXPECT_EQ(origin_of(plain).digest(), origin_of(same).digest());

    const std::string c4 = kRobots + "/centipede-4.xml";
    const Settings grow = with({"Simulator.robotFile=" + kRobots + "/centipede-2.xml",
                                "Simulator.growRobotFiles=" + c4, "Simulator.growAt=0.5"});
    const CheckpointOrigin o = origin_of(grow);
    std::string growth;
    for (const auto& p : o.parts)
        if (p.name == "growth") growth = p.text;
    EXPECT_HAS(growth, "at 0.5 (generation 25): centipede-4 (31 modules, 24 joints");
    const Settings both = with({"Simulator.robotFile=" + kRobots + "/centipede-2.xml",
                                "Simulator.extraRobotFiles=" + c4, "Simulator.bodiesAggregate=min"});
    std::string bodies;
    for (const auto& p : origin_of(both).parts)
        if (p.name == "bodies") bodies = p.text;
    EXPECT_HAS(bodies, "aggregate min: centipede-4 (31 modules");
    EXPECT_NE(settings_digest(both), settings_digest(plain));
    // A checkpoint of the growing run is refused by settings that grow otherwise, naming the schedule.
    const Settings later = with({"Simulator.robotFile=" + kRobots + "/centipede-2.xml",
                                 "Simulator.growRobotFiles=" + c4, "Simulator.growAt=0.75"});
    EXPECT_HAS(input_error([&] { check_origin(o, later, "gen.xml"); }), "growth: checkpoint at 0.5 (generation 25)");
}

} // namespace
} // namespace cic::io
