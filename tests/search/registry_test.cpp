// The search registry (include/cic/search/search.hpp): what Experiment.search
// picks, what it refuses, and the rules of a registration.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "cic/core/error.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/settings.hpp"
#include "cic/io/search_names.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/search/search.hpp"

namespace {

using cic::InputError;
using cic::io::Settings;
using cic::search::search_of;

std::string refusal(const Settings& s) {
    try {
        (void)search_of(s);
    } catch (const InputError& e) {
        return e.message();
    }
    return "(accepted)";
}

TEST(SearchRegistry, AutoPicksTheSearchTheOtherKeysImply) {
    Settings s;   // hypergp: trees
    EXPECT_EQ(search_of(s).name, "generational");
    s.map_elites.enabled = true;
    EXPECT_EQ(search_of(s).name, "map-elites");
    s.map_elites.enabled = false;
    s.neural.switch_share = 0.5;
    EXPECT_EQ(search_of(s).name, "switch-hybrid");
    Settings g;
    g.experiment.type = "gait";
    EXPECT_EQ(search_of(g).name, "evolution-strategy");
    g.map_elites.enabled = true;
    EXPECT_EQ(search_of(g).name, "map-elites");
    Settings sr;
    sr.experiment.type = "symreg";
    EXPECT_EQ(search_of(sr).name, "generational");
}

TEST(SearchRegistry, ANamedSearchIsTakenWhenItFits) {
    Settings s;
    s.experiment.search = "generational";
    EXPECT_EQ(search_of(s).name, "generational");
    s.experiment.search = "map-elites";
    s.map_elites.enabled = true;
    EXPECT_EQ(search_of(s).name, "map-elites");
}

TEST(SearchRegistry, ANamedSearchMustVaryTheTypesGenotypes) {
    Settings s;
    s.experiment.search = "evolution-strategy";
    const std::string m = refusal(s);
    EXPECT_NE(m.find("Experiment.search = evolution-strategy varies gait vectors"), std::string::npos) << m;
    EXPECT_NE(m.find("allowed for it: auto, generational, map-elites, switch-hybrid"), std::string::npos) << m;
    Settings g;
    g.experiment.type = "gait";
    g.experiment.search = "switch-hybrid";
    EXPECT_NE(refusal(g).find("varies trees"), std::string::npos) << refusal(g);
}

TEST(SearchRegistry, AKeyThatAsksForAnotherSearchIsAConflict) {
    Settings s;
    s.experiment.search = "generational";
    s.map_elites.enabled = true;
    const std::string m = refusal(s);
    EXPECT_NE(m.find("MapElites.enabled = 1 asks for the search map-elites"), std::string::npos) << m;
}

TEST(SearchRegistry, ANamedSearchNeedsTheKeysThatAskForIt) {
    Settings g;
    g.experiment.type = "gait";
    g.experiment.search = "map-elites";
    EXPECT_NE(refusal(g).find("Experiment.search = map-elites needs MapElites.enabled = 1"), std::string::npos)
        << refusal(g);
    Settings s;
    s.experiment.search = "switch-hybrid";
    EXPECT_NE(refusal(s).find("needs Neural.switchPatience > 0 or Neural.switchShare > 0"), std::string::npos) << refusal(s);
}

TEST(SearchRegistry, TheReaderRefusesAnUnknownNameWithTheAllowedOnes) {
    try {
        (void)cic::io::read_settings_string(
            "<settings><Experiment><search>generationl</search></Experiment></settings>", "s.xml");
        FAIL() << "accepted";
    } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("search"), std::string::npos) << m;
        EXPECT_NE(m.find("auto, generational, evolution-strategy, map-elites, switch-hybrid"), std::string::npos) << m;
        EXPECT_EQ(e.line(), 1) << m;
    }
}

TEST(SearchRegistry, RegistrationsAreChecked) {
    const auto& first = cic::search::search_kinds().front();
    cic::search::SearchKind again = first;
    EXPECT_THROW(cic::search::register_search(again), std::invalid_argument);   // a name twice
    cic::search::SearchKind incomplete;
    incomplete.name = "incomplete";
    incomplete.forms = {cic::io::GenotypeForm::Vector};
    incomplete.budget_key = "Gait.evaluations";
    EXPECT_THROW(cic::search::register_search(incomplete), std::invalid_argument);   // no load, no make
    EXPECT_EQ(cic::io::find_search_name("incomplete"), nullptr) << "a refused kind left its name behind";
}

// Naming the search `auto` picks anyway is the same run, so the same settings digest
// (a resume from the other's checkpoint gets no "made with other settings" note).
TEST(SearchRegistry, NamingTheSearchAutoPicksKeepsTheDigest) {
    auto same_digest_when_named = [](Settings s, const std::string& name) {
        const std::string as_auto = cic::io::settings_digest(s);
        EXPECT_EQ(cic::io::auto_search_pick(s), name);
        s.experiment.search = name;
        ASSERT_EQ(search_of(s).name, name);
        EXPECT_EQ(cic::io::settings_digest(s), as_auto) << name;
    };
    Settings trees;
    same_digest_when_named(trees, "generational");
    Settings gait;
    gait.experiment.type = "gait";
    same_digest_when_named(gait, "evolution-strategy");
    Settings elites = gait;
    elites.map_elites.enabled = true;
    same_digest_when_named(elites, "map-elites");
    Settings hybrid;
    hybrid.neural.switch_share = 0.5;
    same_digest_when_named(hybrid, "switch-hybrid");
    // What the digest sees is still the settings: the keys that chose the search count.
    EXPECT_NE(cic::io::settings_digest(elites), cic::io::settings_digest(gait));
}

TEST(SearchRegistry, BudgetKeysAreEveryRegisteredSearchs) {
    const auto keys = cic::search::budget_keys();
    for (const char* k : {"Control.minimumFitness", "Control.maximumIterations", "Gait.evaluations",
                          "MapElites.evaluations"})
        EXPECT_NE(std::find(keys.begin(), keys.end(), k), keys.end()) << k;
}

} // namespace
