// MAP-Elites archives (io/archive_xml.hpp): exact round trip, refusal of
// broken or edited files with their line, compatibility with the settings.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cic/core/error.hpp"
#include "cic/io/archive_xml.hpp"
#include "support/files.hpp"

namespace cic::io {
namespace {

ArchiveFile sample(bool trees) {
    ArchiveFile a;
    a.experiment = trees ? "hypergp" : "gait";
    a.settings_digest = "0123abcd";
    a.seed = 18446744073709551615ULL;
    a.batches = 3;
    a.evaluations = 30;
    a.failed = 2;
    a.rng = Rng(9).state();
    a.descriptor = "duty-factor";
    a.grid = gp::GridSpec{{5, 5}, {0, 0}, {1, 1}};
    ArchiveElite e1, e2;
    e1.cell = 1;   // bins 0,1
    e1.fitness = 1.0 / 3.0;
    e1.descriptor = {0.1, 0.2};
    e2.cell = 24;   // bins 4,4 (1.0 falls in the last bin)
    e2.fitness = -0.25;
    e2.descriptor = {1.0, 0.9999999999999999};
    if (trees) {
        e1.genotype = {tree::Tree::parse("(add x0 (sin x3))"), tree::Tree::parse("1")};
        e2.genotype = {tree::Tree::parse("(gauss x1)"), tree::Tree::parse("(mul -1 x0)")};
    } else {
        e1.x = {0.1, 1.0 / 3.0};
        e2.x = {0.0, 1.0};
    }
    a.elites = {e1, e2};
    return a;
}

std::string error_of(const std::string& text) {
    try {
        parse_archive(text, "a.xml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(ArchiveXml, RoundTripsExactly) {
    for (bool trees : {false, true}) {
        const ArchiveFile a = sample(trees);
        const std::string text = to_xml(a);
        const ArchiveFile back = parse_archive(text, "a.xml");
        EXPECT_EQ(to_xml(back), text);
        EXPECT_EQ(back.seed, a.seed);
        EXPECT_EQ(back.rng, a.rng);
        EXPECT_EQ(back.elites[0].fitness, 1.0 / 3.0);   // bit for bit
        EXPECT_EQ(back.elites[1].descriptor, a.elites[1].descriptor);
        EXPECT_EQ(back.best()->cell, 1u);
        EXPECT_EQ(back.at(24)->fitness, -0.25);
        EXPECT_EQ(back.at(2), nullptr);
    }
}

TEST(ArchiveXml, SavedFileLoads) {
    const auto dir = cic::testing::temp_dir("archive-xml");
    cic::testing::write_text(dir / "population.xml", to_xml(sample(true)));
    EXPECT_EQ(load_archive(dir / "population.xml").elites.size(), 2u);
    std::filesystem::remove_all(dir);
}

TEST(ArchiveXml, BrokenOrEditedFilesAreRefusedWithTheirLine) {
    const std::string text = to_xml(sample(false));
    EXPECT_NE(error_of(text.substr(0, text.size() / 2)), "(no error)");
    // An elite moved to another cell than its descriptor's.
    EXPECT_NE(error_of(replaced(text, "cell=\"24\"", "cell=\"23\"")).find("a.xml:"), std::string::npos);
    EXPECT_NE(error_of(replaced(text, "cell=\"24\"", "cell=\"23\"")).find("has a descriptor of cell 24"),
              std::string::npos);
    EXPECT_NE(error_of(replaced(text, "cell=\"24\"", "cell=\"25\"")).find("past the grid's 25 cells"),
              std::string::npos);
    EXPECT_NE(error_of(replaced(text, "count=\"2\"", "count=\"3\"")).find("truncated or edited"), std::string::npos);
    EXPECT_NE(error_of(replaced(text, "descriptor=\"0.10000000000000001 0.20000000000000001\"", "descriptor=\"0.1\""))
                  .find("descriptor of 1 values"),
              std::string::npos);
    EXPECT_NE(error_of(replaced(text, "fitness=\"-0.25\"", "fitness=\"nan\"")), "(no error)");
    EXPECT_NE(error_of(replaced(text, "<x>", "<tree>1</tree><x>")).find("either"), std::string::npos);
    EXPECT_NE(error_of(replaced(text, "failed=\"2\"", "failed=\"31\"")), "(no error)");
    EXPECT_NE(error_of(replaced(text, "descriptor=\"duty-factor\"", "descriptor=\"speed\"")).find("allowed"),
              std::string::npos);
    // The one strictness policy: unknown names get a suggestion.
    EXPECT_NE(error_of(replaced(text, "<elite cell", "<elite cel")).find("did you mean"), std::string::npos);
    EXPECT_NE(error_of(replaced(text, "<archive ", "<!DOCTYPE a [<!ENTITY e \"x\">]><archive ")), "(no error)");
    // Elites out of cell order (the second moved before the first).
    const auto first = text.find("    <elite cell=\"1\""), second = text.find("    <elite cell=\"24\"");
    const auto end = text.find("  </elites>");
    std::string swapped = text.substr(0, first) + text.substr(second, end - second) +
                          text.substr(first, second - first) + text.substr(end);
    EXPECT_NE(error_of(swapped).find("rising cell order"), std::string::npos);
    EXPECT_EQ(error_of(text), "(no error)");
}

TEST(ArchiveXml, ASettingsMismatchIsRefused) {
    Settings s;
    s.experiment.type = "gait";
    s.map_elites.enabled = true;
    const ArchiveFile a = sample(false);
    s.map_elites.batch = 10;   // the sample's 30 evaluations are 3 batches of 10
    const gp::GridSpec grid{{5, 5}, {0, 0}, {1, 1}};
    EXPECT_NO_THROW(check_compatible(a, s, grid, 2, "a.xml"));
    EXPECT_THROW(check_compatible(a, s, gp::GridSpec{{4, 5}, {0, 0}, {1, 1}}, 2, "a.xml"), InputError);   // bins
    s.map_elites.descriptor = sim::Descriptor::Omni;
    EXPECT_THROW(check_compatible(a, s, grid, 2, "a.xml"), InputError);
    s.map_elites.descriptor = sim::Descriptor::DutyFactor;
    s.experiment.type = "hypergp";
    EXPECT_THROW(check_compatible(a, s, grid, 2, "a.xml"), InputError);
    s.experiment.type = "gait";
    s.map_elites.enabled = false;
    EXPECT_THROW(check_compatible(a, s, grid, 2, "a.xml"), InputError);
}

std::string compatibility_error(const ArchiveFile& a, const Settings& s, std::size_t dimension) {
    try {
        check_compatible(a, s, gp::GridSpec{{5, 5}, {0, 0}, {1, 1}}, dimension, "a.xml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

// Issue 39, class 2: an archive is checked as strictly as a population.
TEST(ArchiveXml, AnEditedEliteIsRefusedByItsHash) {
    const std::string text = to_xml(sample(false));
    ASSERT_NE(text.find(" hash=\""), std::string::npos);
    // An elite's fitness edited to 99 would end a run as "minimum fitness reached".
    const std::string e = error_of(replaced(text, "fitness=\"-0.25\"", "fitness=\"99\""));
    EXPECT_NE(e.find("a.xml:"), std::string::npos) << e;
    EXPECT_NE(e.find("<elite cell=\"24\" hash="), std::string::npos) << e;
    EXPECT_NE(e.find("edited by hand"), std::string::npos) << e;
    // Issue 56: never the expected hash, which pasted in would make the edit pass.
    for (auto elite : sample(false).elites)
        if (elite.fitness == -0.25) {
            elite.fitness = 99;
            EXPECT_EQ(e.find(cic::io::elite_hash(elite)), std::string::npos) << e;
        }
    EXPECT_NE(error_of(replaced(to_xml(sample(true)), "(gauss x1)", "(gauss x0)")).find("edited by hand"),
              std::string::npos);
}

// Issue 56: a version 2 archive's contentHash covers what no elite's hash does
// (batches, evaluations, the random state, the origin); a version 1 file loads
// without it, its best elite's replay the proof.
TEST(ArchiveXml, TheContentHashCoversTheCounters) {
    const std::string text = to_xml(sample(false));
    ASSERT_NE(text.find(" version=\"2\""), std::string::npos);
    const auto at = text.find(" batches=\"");
    const std::string batches = text.substr(at, text.find('"', at + 10) + 1 - at);
    const std::string e = error_of(replaced(text, batches, " batches=\"1\""));
    EXPECT_NE(e.find("does not match what the MAP-Elites archive holds (edited by hand?)"), std::string::npos) << e;
    const auto h = text.find(" contentHash=\"");
    const std::string old = replaced(text.substr(0, h) + text.substr(h + 31), " version=\"2\"", " version=\"1\"");
    EXPECT_EQ(error_of(old), "(no error)");
    EXPECT_NE(error_of(replaced(old, " version=\"1\"", " version=\"2\"")).find("has no contentHash"), std::string::npos);
}

TEST(ArchiveXml, DescriptorsOutsideTheGridAndGenesOutsideTheBoxAreRefused) {
    const std::string text = to_xml(sample(false));
    const std::string d = error_of(replaced(text, "descriptor=\"0.10000000000000001 0.20000000000000001\"",
                                            "descriptor=\"-0.5 0.20000000000000001\""));
    EXPECT_NE(d.find("a.xml:"), std::string::npos) << d;
    EXPECT_NE(d.find("outside the grid's [0, 1]"), std::string::npos) << d;
    EXPECT_NE(error_of(replaced(text, "descriptor=\"1 0.99999999999999989\"", "descriptor=\"1.5 0.99999999999999989\""))
                  .find("outside the grid"),
              std::string::npos);
    const std::string x = error_of(replaced(text, "<x>0 1</x>", "<x>0 1.25</x>"));
    EXPECT_NE(x.find("outside the unit box"), std::string::npos) << x;
}

TEST(ArchiveXml, ElitesTheSettingsCannotTakeAreRefusedWithTheirLine) {
    Settings s;
    s.experiment.type = "gait";
    s.map_elites.enabled = true;
    s.map_elites.batch = 10;
    const ArchiveFile gait = sample(false);
    EXPECT_EQ(compatibility_error(gait, s, 2), "(no error)");
    // An elite of the wrong length, with its line.
    const ArchiveFile read = parse_archive(to_xml(gait), "a.xml");
    const std::string length = compatibility_error(read, s, 3);
    EXPECT_NE(length.find("a.xml:" + std::to_string(read.elites[0].line) + ": <elite cell=\"1\"> has 2 parameters, "
                          "these settings make 3"),
              std::string::npos)
        << length;
    // Evaluations that are not a whole number of batches.
    s.map_elites.batch = 7;
    EXPECT_NE(compatibility_error(gait, s, 2).find("is not its 3 batches of MapElites.batch 7 (21)"), std::string::npos)
        << compatibility_error(gait, s, 2);
    // A tree using x9 when there are 4 variables (the population reader refuses it too).
    s.experiment.type = "hypergp";
    s.map_elites.batch = 10;
    s.gp.trees_per_genotype = 2;
    ArchiveFile trees = sample(true);
    trees.experiment = "hypergp";
    EXPECT_EQ(compatibility_error(trees, s, 0), "(no error)");
    trees.elites[1].genotype[0] = tree::Tree::parse("(gauss x9)");
    EXPECT_NE(compatibility_error(trees, s, 0).find("<elite cell=\"24\"> uses variable x9, but "
                                                   "GP.terminalVariableCount is 4"),
              std::string::npos)
        << compatibility_error(trees, s, 0);
    trees = sample(true);
    s.gp.trees_per_genotype = 1;
    EXPECT_NE(compatibility_error(trees, s, 0).find("has 2 trees"), std::string::npos);
}

} // namespace
} // namespace cic::io
