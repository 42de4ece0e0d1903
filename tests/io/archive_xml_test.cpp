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
    const gp::GridSpec grid{{5, 5}, {0, 0}, {1, 1}};
    EXPECT_NO_THROW(check_compatible(a, s, grid, "a.xml"));
    EXPECT_THROW(check_compatible(a, s, gp::GridSpec{{4, 5}, {0, 0}, {1, 1}}, "a.xml"), InputError);   // bins
    s.map_elites.descriptor = sim::Descriptor::Omni;
    EXPECT_THROW(check_compatible(a, s, grid, "a.xml"), InputError);
    s.map_elites.descriptor = sim::Descriptor::DutyFactor;
    s.experiment.type = "hypergp";
    EXPECT_THROW(check_compatible(a, s, grid, "a.xml"), InputError);
    s.experiment.type = "gait";
    s.map_elites.enabled = false;
    EXPECT_THROW(check_compatible(a, s, grid, "a.xml"), InputError);
}

} // namespace
} // namespace cic::io
