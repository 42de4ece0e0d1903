// Gait checkpoints: exact round trip, refusal of broken files, compatibility.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cic/core/error.hpp"
#include "cic/io/gait_xml.hpp"
#include "support/files.hpp"

namespace cic::io {
namespace {

GaitFile sample() {
    GaitFile g;
    g.settings_digest = "0123abcd";
    g.optimizer = "cmaes";
    g.seed = 18446744073709551615ULL;   // the largest seed survives
    g.generation = 3;
    g.evaluations = 40;
    g.dimension = 3;
    g.population = {{{0.1, 1.0 / 3.0, 0.9999999999999999}, -0.5}, {{0.0, 1.0, 0.5}, 2.25}};
    g.champion = {{0.0, 1.0, 0.5}, 2.25};
    for (int i = 0; i < 40; ++i) g.history.push_back(std::sin(i) / 7.0);
    return g;
}

std::string error_of(const std::string& text) {
    try {
        parse_gait(text, "g.xml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(GaitXml, RoundTripsExactly) {
    const GaitFile g = sample();
    const std::string text = to_xml(g);
    const GaitFile back = parse_gait(text, "g.xml");
    EXPECT_EQ(to_xml(back), text);
    EXPECT_EQ(back.seed, g.seed);
    EXPECT_EQ(back.population[0].x[1], 1.0 / 3.0);   // bit for bit
    EXPECT_EQ(back.history, g.history);
    EXPECT_EQ(back.champion.fitness, 2.25);
}

TEST(GaitXml, SavedFileIsRecognisedAndLoads) {
    const auto dir = cic::testing::temp_dir("gait-xml");
    cic::testing::write_text(dir / "population.xml", to_xml(sample()));
    EXPECT_TRUE(is_gait_file(dir / "population.xml"));
    EXPECT_EQ(load_gait(dir / "population.xml").generation, 3);
    cic::testing::write_text(dir / "other.xml", "<population format=\"cic-population\"/>");
    EXPECT_FALSE(is_gait_file(dir / "other.xml"));
    std::filesystem::remove_all(dir);
}

TEST(GaitXml, BrokenFilesAreRefusedWithTheirLine) {
    const std::string text = to_xml(sample());
    EXPECT_NE(error_of(text.substr(0, text.size() / 2)), "(no error)");
    std::string bad = text;
    bad.replace(bad.find("0.5"), 3, "0.5x");
    EXPECT_NE(error_of(bad).find("g.xml:"), std::string::npos) << error_of(bad);
    EXPECT_NE(error_of(bad).find("is not a valid number"), std::string::npos) << error_of(bad);
    bad = text;
    bad.replace(bad.find("0.5"), 3, "1e-400");   // issue 39: said as an underflow, not an invalid number
    EXPECT_NE(error_of(bad).find("\"1e-400\" underflows"), std::string::npos) << error_of(bad);
    bad = text;
    bad.replace(bad.find(" 0.5"), 4, "");   // a point with one parameter too few
    EXPECT_NE(error_of(bad).find("parameters"), std::string::npos) << error_of(bad);
}

// A run with IPOP restarts records them; files without the element (restarts
// none, or older runs) load as before and write no element.
TEST(GaitXml, RestartsRoundTripAndAreChecked) {
    const std::string plain = to_xml(sample());
    EXPECT_EQ(plain.find("<restarts"), std::string::npos);
    EXPECT_FALSE(parse_gait(plain, "g.xml").restarts.has_value());

    GaitFile g = sample();
    g.restarts = GaitRestartRecord{2, 2, {1, 3}};
    const std::string text = to_xml(g);
    EXPECT_NE(text.find("<restarts count=\"2\" populationSize=\"2\" generations=\"1 3\"/>"), std::string::npos)
        << text;
    const GaitFile back = parse_gait(text, "g.xml");
    ASSERT_TRUE(back.restarts.has_value());
    EXPECT_EQ(back.restarts->count, 2);
    EXPECT_EQ(back.restarts->population_size, 2);
    EXPECT_EQ(back.restarts->generations, (std::vector<int>{1, 3}));
    EXPECT_EQ(to_xml(back), text);
    g.restarts = GaitRestartRecord{0, 2, {}};
    EXPECT_EQ(parse_gait(to_xml(g), "g.xml").restarts->count, 0);

    auto broken = [&](const std::string& from, const std::string& to) {
        std::string bad = text;
        bad.replace(bad.find(from), from.size(), to);
        return error_of(bad);
    };
    EXPECT_NE(broken("count=\"2\" populationSize", "count=\"3\" populationSize").find("lists 2 generations"),
              std::string::npos);
    EXPECT_NE(broken("populationSize=\"2\"", "populationSize=\"7\"").find("but 2 candidates"), std::string::npos);
    EXPECT_NE(broken("generations=\"1 3\"", "generations=\"3 1\"").find("must rise"), std::string::npos);
    EXPECT_NE(broken("generations=\"1 3\"", "generations=\"1 4\"").find("must rise, each in [1, 3]"),
              std::string::npos);
    EXPECT_NE(broken("count=\"2\" populationSize", "count=\"-1\" populationSize").find(">= 0"), std::string::npos);
    EXPECT_NE(broken("generations=\"1 3\"", "generations=\"1 x\"").find("g.xml:"), std::string::npos);
    const std::string twice = broken("<restarts ", "<restarts count=\"0\" populationSize=\"2\" generations=\"\"/><restarts ");
    EXPECT_NE(twice.find("appears twice"), std::string::npos) << twice;
}

// Switch-HybrID's gait phase: <handover> round-trips exactly, is checked, and
// belongs to settings that switch.
TEST(GaitXml, HandoverRoundTripsAndIsChecked) {
    GaitFile g = sample();
    g.handover = GaitHandover{24, 1279, {0.25, -1.0 / 6.0, 1e-17}};
    const std::string text = to_xml(g);
    EXPECT_NE(text.find("<handover generation=\"24\" evaluations=\"1279\">"), std::string::npos) << text;
    const GaitFile back = parse_gait(text, "g.xml");
    EXPECT_EQ(to_xml(back), text);
    ASSERT_TRUE(back.handover.has_value());
    EXPECT_EQ(back.handover->x, g.handover->x);   // bit for bit
    EXPECT_EQ(back.handover->evaluations, 1279);
    EXPECT_EQ(to_xml(sample()).find("handover"), std::string::npos);   // none without a switch
    auto broken = [&](const std::string& from, const std::string& to) {
        std::string t = text;
        t.replace(t.find(from), from.size(), to);
        return error_of(t);
    };
    EXPECT_NE(broken("1.0000000000000001e-17<", "<").find("<handover> has 2 parameters"), std::string::npos);
    EXPECT_NE(broken("generation=\"24\"", "generation=\"-1\"").find(">= 0"), std::string::npos);
    Settings s;
    s.experiment.type = "hypergp";
    s.neural.substrate = "gait";
    s.neural.switch_patience = 5;
    EXPECT_NO_THROW(check_compatible(g, s, 3, "g.xml"));
    EXPECT_THROW(check_compatible(sample(), s, 3, "g.xml"), InputError);   // a gait run's checkpoint
    s.neural.switch_patience = 0;
    EXPECT_THROW(check_compatible(g, s, 3, "g.xml"), InputError);          // settings that never switch
}

// Issue 39: an edited fitness (champion, candidate or history) would be
// believed on resume; the content hash notices it. Issue 56: a version 2 file
// (today's) without one is refused; a version 1 file, written before the hash
// (no contentHash), loads as before: its champion's replay is its proof.
TEST(GaitXml, AnEditedStateIsRefusedByItsContentHash) {
    const std::string text = to_xml(sample());
    ASSERT_NE(text.find("contentHash=\""), std::string::npos);
    std::string edited = text;
    edited.replace(edited.find("fitness=\"2.25\""), 14, "fitness=\"99\"");   // the champion
    const std::string e = error_of(edited);
    EXPECT_NE(e.find("g.xml:2:"), std::string::npos) << e;
    EXPECT_NE(e.find("contentHash"), std::string::npos) << e;
    EXPECT_NE(e.find("edited by hand"), std::string::npos) << e;
    // Issue 56: never the expected hash, which pasted in would make the edit pass.
    cic::io::GaitFile faked = sample();
    faked.champion.fitness = 99;
    EXPECT_EQ(e.find(cic::io::content_hash(faked)), std::string::npos) << e;
    std::string legacy = text;
    const auto at = legacy.find(" contentHash=\"");
    legacy.erase(at, legacy.find('"', at + 14) + 1 - at);
    EXPECT_NE(error_of(legacy).find("has no contentHash"), std::string::npos) << error_of(legacy);
    legacy.replace(legacy.find(" version=\"2\""), 12, " version=\"1\"");
    EXPECT_EQ(error_of(legacy), "(no error)");
    edited = legacy;
    edited.replace(edited.find("fitness=\"2.25\""), 14, "fitness=\"99\"");
    EXPECT_EQ(error_of(edited), "(no error)");   // nothing to check against here: the champion's replay refuses it
    // Version 1's own hash, over the search's state, is still checked where a file has one.
    std::string v1 = text;
    v1.replace(v1.find(" version=\"2\""), 12, " version=\"1\"");
    v1.replace(v1.find(" contentHash=\"") + 14, 16, cic::io::content_hash(sample()));
    EXPECT_EQ(error_of(v1), "(no error)");
    v1.replace(v1.find("fitness=\"2.25\""), 14, "fitness=\"99\"");
    EXPECT_NE(error_of(v1).find("edited by hand"), std::string::npos);
}

TEST(GaitXml, TheOriginRoundTripsAndAnEditedOneIsRefused) {
    GaitFile g = sample();
    g.origin = CheckpointOrigin{{{"experiment", "gait"}, {"robot", "R1 (3 modules, 2 joints; geometry 00)"}}, 0};
    const std::string text = to_xml(g);
    const GaitFile back = parse_gait(text, "g.xml");
    ASSERT_TRUE(back.origin.has_value());
    EXPECT_EQ(back.origin->parts, g.origin->parts);
    EXPECT_EQ(to_xml(back), text);
    std::string edited = text;
    edited.replace(edited.find("R1 (3"), 5, "R2 (3");
    EXPECT_NE(error_of(edited).find("does not match its parts"), std::string::npos) << error_of(edited);
    EXPECT_FALSE(parse_gait(to_xml(sample()), "g.xml").origin.has_value());
}

TEST(GaitXml, ACheckpointOfOtherSettingsIsRefused) {
    Settings s;
    s.experiment.type = "gait";
    EXPECT_NO_THROW(check_compatible(sample(), s, 3, "g.xml"));
    EXPECT_THROW(check_compatible(sample(), s, 5, "g.xml"), InputError);       // another robot
    s.gait.optimizer = GaitOptimizer::Sade;
    EXPECT_THROW(check_compatible(sample(), s, 3, "g.xml"), InputError);       // another optimiser
    s.experiment.type = "hypergp";
    EXPECT_THROW(check_compatible(sample(), s, 3, "g.xml"), InputError);
}

} // namespace
} // namespace cic::io
