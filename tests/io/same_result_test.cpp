// A choice that cannot change a result changes no record of it
// (SettingKey::same_result_as_default): Simulator.collisionSpace 0 (simple)
// and 1 (sweep, the default since issue 55) give the same bits, so they give
// the same settings digest, checkpoint origin and resume comparison, and a
// checkpoint written when 1 was recorded apart (issue 38's runs) still holds.
#include <gtest/gtest.h>

#include <string>

#include "cic/core/error.hpp"
#include "cic/io/checkpoint_origin.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings_table.hpp"
#include "cic/sim/config.hpp"

namespace cic::io {
namespace {

Settings with_space(int space) {
    Settings s;
    s.experiment.type = "gait";
    s.sim.collision_space = space;
    return s;
}

TEST(SameResult, SweepIsTheDefaultAndSimpleComputesAsIt) {
    EXPECT_EQ(sim::SimConfig{}.collision_space, sim::kCollisionSweep);
    const SettingKey* k = find_setting("Simulator", "collisionSpace");
    ASSERT_NE(k, nullptr);
    EXPECT_TRUE(computes_as_default(*k, "0"));
    EXPECT_TRUE(computes_as_default(*k, "1"));
    EXPECT_FALSE(computes_as_default(*k, "2"));
    EXPECT_TRUE(same_result(*k, "0", "1"));
    EXPECT_FALSE(same_result(*k, "0", "2"));
    // Every other key computes as its default only at its default.
    for (const auto& key : settings_table())
        if (key.section + "." + key.key != "Simulator.collisionSpace") EXPECT_TRUE(key.same_result_as_default.empty());
}

TEST(SameResult, DigestAndOriginDoNotTellSimpleFromSweep) {
    EXPECT_EQ(settings_digest(with_space(0)), settings_digest(with_space(1)));
    EXPECT_NE(settings_digest(with_space(0)), settings_digest(with_space(2)));
    EXPECT_EQ(origin_of(with_space(0)).digest(), origin_of(with_space(1)).digest());
    EXPECT_NE(origin_of(with_space(0)).digest(), origin_of(with_space(2)).digest());
    // Sap is named where it differs.
    try {
        check_origin(origin_of(with_space(2)), with_space(1), "population.xml");
        FAIL() << "sap taken for sweep";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("collisionSpace checkpoint 2"), std::string::npos) << e.what();
    }
}

// Before issue 55 the digest counted an explicit 1 apart (the legacy rule),
// and the origin's simulator part named it: such a checkpoint is these settings'.
TEST(SameResult, CheckpointsThatNamedSweepStillHold) {
    const Settings s = with_space(1);
    EXPECT_NE(settings_digest(s, DigestRule::Legacy), settings_digest(s));
    EXPECT_EQ(settings_digest(with_space(0), DigestRule::Legacy), settings_digest(with_space(0)));
    CheckpointOrigin old = origin_of(s);
    for (auto& p : old.parts)
        if (p.name == "simulator") p.text = p.text.empty() ? "collisionSpace=1" : p.text + " collisionSpace=1";
    EXPECT_NO_THROW(check_origin(old, with_space(0), "population.xml"));
    EXPECT_NO_THROW(check_origin(old, with_space(1), "population.xml"));
    EXPECT_THROW(check_origin(old, with_space(2), "population.xml"), InputError);
}

} // namespace
} // namespace cic::io
