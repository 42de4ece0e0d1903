// Population files: round trip, hand edits, and refusal of broken or foreign files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "cic/io/population_xml.hpp"
#include "cic/io/xml.hpp"

namespace cic::io {
namespace {

PopulationFile sample() {
    PopulationFile p;
    p.experiment = "symreg";
    p.settings_digest = "abc123";
    p.variables = 2;
    p.functions = {"add", "mul", "sin"};
    p.trees = 2;
    p.population.generation = 7;
    p.state.seed = 99;
    p.state.rng = Rng(5);
    p.state.rng.next();
    p.state.next_id = 40;
    p.state.evaluations = 321;
    p.state.bloat = {6, 5, -0.125};
    for (int i = 0; i < 3; ++i) {
        auto ind = std::make_shared<gp::Individual>();
        ind->id = 30 + static_cast<std::uint64_t>(i);
        ind->genotype = {tree::Tree::parse("(add x0 (mul x1 0.10000000000000001))"),
                         tree::Tree::parse("(sin -1)")};
        ind->fitness = -1.0 / 3.0 * (i + 1);
        ind->evaluated = true;
        ind->parents = {3, 4};
        if (i == 1) ind->illegal = true;
        if (i == 2) {
            ind->failed = true;
            ind->failure = "physics blow-up: body 3 at 1e+05 m";
        }
        p.population.individuals.push_back(ind);
    }
    return p;
}

TEST(PopulationXml, RoundTripsExactly) {
    const auto p = sample();
    const std::string text = to_xml(p);
    const auto q = parse_population(text, "p.xml");
    EXPECT_EQ(to_xml(q), text);
    EXPECT_EQ(q.state.rng.state(), p.state.rng.state());
    EXPECT_EQ(q.population[0].fitness, p.population[0].fitness);   // bit-exact doubles
    EXPECT_TRUE(q.population[1].illegal);
    EXPECT_FALSE(q.population[0].illegal);
    EXPECT_EQ(q.state.bloat.best_fitness, -0.125);
    EXPECT_EQ(q.population.generation, 7);
    EXPECT_TRUE(q.population[2].failed);
    EXPECT_EQ(q.population[2].failure, "physics blow-up: body 3 at 1e+05 m");
    EXPECT_FALSE(q.population[1].failed);
}

TEST(PopulationXml, MarksAreTheKnownOnes) {
    const std::string text = to_xml(sample());
    const std::string illegal = "<attribute key=\"illegal\">1</attribute>";
    ASSERT_NE(text.find(illegal), std::string::npos) << text;
    auto with = [&](const std::string& mark) {
        std::string t = text;
        t.replace(t.find(illegal), illegal.size(), mark);
        return t;
    };
    try {
        parse_population(with("<attribute key=\"favourite\">1</attribute>"), "marks.xml");
        FAIL() << "expected an error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("unknown attribute key 'favourite'; allowed: edited, failed, illegal"),
                  std::string::npos) << e.what();
        EXPECT_GT(e.line(), 0);
    }
    EXPECT_THROW(parse_population(with("<attribute key=\"illegal\">yes</attribute>"), "marks.xml"), InputError);
}

TEST(PopulationXml, HandEditedTreeLoadsAndIsEvaluatedAgain) {
    std::string text = to_xml(sample());
    const std::string from = "<tree>(sin -1)</tree>";
    text.replace(text.find(from), from.size(), "<tree>(sin (add x1 2.5))</tree>");
    const auto q = parse_population(text, "edited.xml");
    EXPECT_EQ(q.population[0].genotype[1].to_string(), "(sin (add x1 2.5))");
    EXPECT_FALSE(q.population[0].evaluated);   // its stored fitness belonged to the old tree
    EXPECT_TRUE(q.population[0].edited);
    EXPECT_TRUE(q.population[1].evaluated);    // untouched individuals keep theirs
}

TEST(PopulationXml, TruncatedFileIsRefusedWithItsLine) {
    const std::string text = to_xml(sample());
    const std::string cut = text.substr(0, text.size() * 2 / 3);
    try {
        parse_population(cut, "cut.xml");
        FAIL() << "expected an error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "cut.xml");
        EXPECT_GT(e.line(), 0) << e.what();
    }
}

TEST(PopulationXml, CorruptTreeIsRefusedWithItsLine) {
    std::string text = to_xml(sample());
    const std::string from = "<tree>(sin -1)</tree>";
    text.replace(text.find(from), from.size(), "<tree>(sin -1</tree>");
    try {
        parse_population(text, "bad.xml");
        FAIL() << "expected an error";
    } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("bad.xml:"), std::string::npos) << m;
        EXPECT_NE(m.find("bad tree"), std::string::npos) << m;
        EXPECT_GT(e.line(), 1);
    }
}

TEST(PopulationXml, CountMismatchAndBadNumbersAreRefused) {
    std::string text = to_xml(sample());
    auto pos = text.find("count=\"3\"");
    ASSERT_NE(pos, std::string::npos);
    std::string t1 = text;
    t1.replace(pos, 9, "count=\"4\"");
    EXPECT_THROW(parse_population(t1, "a.xml"), InputError);
    std::string t2 = text;
    pos = t2.find("fitness=\"");
    t2.replace(pos, 9, "fitness=\"x");
    EXPECT_THROW(parse_population(t2, "b.xml"), InputError);
    EXPECT_THROW(parse_population("<settings/>", "c.xml"), InputError);
}

TEST(PopulationXml, SaveIsAtomicAndLeavesNoTemporaries) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("cic-pop-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const auto p = sample();
    save_population(dir / "population.xml", p);
    save_population(dir / "population.xml", p);
    int files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 1);
    EXPECT_EQ(to_xml(load_population(dir / "population.xml")), to_xml(p));
    fs::remove_all(dir);
}

// Offset-HybrID's direct offsets: saved exactly, covered by the hash (an edited
// offset is noticed like an edited tree), and checked: count, finite, in range.
PopulationFile with_offsets() {
    PopulationFile p = sample();
    p.experiment = "hypergp";
    p.offsets = 3;
    p.offset_limit = 2;
    double d = 0.1;
    for (auto& ind : p.population) ind->direct = {d, -1.0 / 3.0, 2.0}, d += 0.7;
    return p;
}

TEST(PopulationXml, DirectOffsetsRoundTripExactly) {
    const auto p = with_offsets();
    const std::string text = to_xml(p);
    EXPECT_NE(text.find("offsets=\"3\" offsetLimit=\"2\""), std::string::npos) << text;
    const auto q = parse_population(text, "p.xml");
    EXPECT_EQ(to_xml(q), text);
    EXPECT_EQ(q.offsets, 3u);
    for (std::size_t i = 0; i < q.population.size(); ++i) {
        EXPECT_EQ(q.population[i].direct, p.population[i].direct);   // bit-exact doubles
        EXPECT_TRUE(q.population[i].evaluated);
        EXPECT_FALSE(q.population[i].edited);
    }
    // Without offsets the file is as before: no attribute, no element.
    const std::string plain = to_xml(sample());
    EXPECT_EQ(plain.find("offsets"), std::string::npos);
    // The writer refuses an individual whose offsets the header does not count.
    auto bad = with_offsets();
    bad.population.individuals[1]->direct.pop_back();
    EXPECT_THROW(to_xml(bad), std::logic_error);
}

TEST(PopulationXml, AnEditedOffsetIsNoticedLikeAnEditedTree) {
    std::string text = to_xml(with_offsets());
    const std::string from = "<offsets>0.10000000000000001 ";
    ASSERT_NE(text.find(from), std::string::npos) << text;
    text.replace(text.find(from), from.size(), "<offsets>0.25 ");
    const auto q = parse_population(text, "edited.xml");
    EXPECT_EQ(q.population[0].direct[0], 0.25);
    EXPECT_FALSE(q.population[0].evaluated);
    EXPECT_TRUE(q.population[0].edited);
    EXPECT_TRUE(q.population[1].evaluated);
}

TEST(PopulationXml, BadOffsetsAreRefusedWithTheirLine) {
    const std::string text = to_xml(with_offsets());
    const std::string from = "<offsets>0.10000000000000001 -0.33333333333333331 2</offsets>";
    ASSERT_NE(text.find(from), std::string::npos) << text;
    auto refused = [&](const std::string& to, const std::string& says) {
        std::string t = text;
        t.replace(t.find(from), from.size(), to);
        try {
            parse_population(t, "bad.xml");
            ADD_FAILURE() << "accepted " << to;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
            EXPECT_GT(e.line(), 1) << e.what();
        }
    };
    refused("<offsets>0.1 0.2</offsets>", "2 offsets, the <genotype> declares 3");
    refused("<offsets>0.1 0.2 0.3 0.4</offsets>", "4 offsets, the <genotype> declares 3");
    refused("<offsets>0.1 2.5 0.3</offsets>", "outside [-2, 2]");
    refused("<offsets>0.1 nan 0.3</offsets>", "offset");
    refused("", "has no <offsets>");
    // Offsets where the header declares none.
    std::string t = to_xml(sample());
    const std::string tree = "<tree>(sin -1)</tree>";
    t.replace(t.find(tree), tree.size(), tree + "<offsets>0.5</offsets>");
    EXPECT_THROW(parse_population(t, "none.xml"), InputError);
}

// Switch-HybrID's stagnation clock: saved exactly, checked, absent elsewhere.
TEST(PopulationXml, SwitchClockRoundTripsAndIsChecked) {
    PopulationFile p = sample();
    p.switch_clock = PopulationFile::SwitchClock{-1.0 / 3.0, 5};
    const std::string text = to_xml(p);
    const auto q = parse_population(text, "p.xml");
    EXPECT_EQ(to_xml(q), text);
    ASSERT_TRUE(q.switch_clock.has_value());
    EXPECT_EQ(q.switch_clock->best, -1.0 / 3.0);
    EXPECT_EQ(q.switch_clock->best_generation, 5);
    EXPECT_EQ(to_xml(sample()).find("<switch"), std::string::npos);
    std::string later = text;
    later.replace(later.find("bestGeneration=\"5\""), 18, "bestGeneration=\"8\"");   // after generation 7
    EXPECT_THROW(parse_population(later, "p.xml"), InputError);
}

TEST(PopulationXml, IncompatibleSettingsAreRefused) {
    Settings s;
    s.experiment.type = "symreg";
    s.gp.primitives.variable_count = 4;
    auto p = describe(s);
    p.population = sample().population;
    p.trees = 2;
    try {
        check_compatible(p, s, "pop.xml");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("numberOfTreesInForestGenotype"), std::string::npos) << e.what();
    }
    p.trees = 1;
    p.variables = 1;
    try {
        check_compatible(p, s, "pop.xml");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("terminalVariableCount 1"), std::string::npos) << e.what();
    }
}

// A growing robot's body (io/bodies.hpp): <body index>, only when given.
TEST(PopulationXml, AGrowingRobotsBodyRoundTrips) {
    PopulationFile p = sample();
    EXPECT_EQ(to_xml(p).find("<body"), std::string::npos);
    EXPECT_FALSE(parse_population(to_xml(p), "p.xml").body.has_value());
    p.body = 2;
    const PopulationFile back = parse_population(to_xml(p), "p.xml");
    ASSERT_TRUE(back.body.has_value());
    EXPECT_EQ(*back.body, 2u);
    EXPECT_EQ(to_xml(back), to_xml(p));
}

} // namespace
} // namespace cic::io

namespace cic::io {
namespace {

std::string error_text(const std::string& text) {
    try {
        parse_population(text, "p.xml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

// Issue 56: version 2 files hold a contentHash over every value but the trees
// and offsets: a fitness, a counter, the generation or the origin edited by
// hand is refused, without the expected value (pasted in, it would pass).
TEST(PopulationXml, TheContentHashCoversEveryValueButTheTrees) {
    const std::string text = to_xml(sample());
    ASSERT_NE(text.find(" version=\"2\""), std::string::npos);
    ASSERT_NE(text.find(" contentHash=\""), std::string::npos);
    auto edited = [&](const std::string& from, const std::string& to) {
        std::string t = text;
        EXPECT_NE(t.find(from), std::string::npos) << from;
        return t.replace(t.find(from), from.size(), to);
    };
    for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
             {"generation=\"7\"", "generation=\"6\""},
             {"evaluations=\"321\"", "evaluations=\"300\""},
             {"nextId=\"40\"", "nextId=\"41\""},
             {"fitness=\"-0.33333333333333331\"", "fitness=\"45\""}}) {
        const std::string t = edited(from, to);
        const std::string e = error_text(t);
        EXPECT_NE(e.find("does not match what the population file holds (edited by hand?)"), std::string::npos) << e;
        // The hash the edited file would need: that of the same values written again.
        std::string as_old = t;
        as_old.replace(as_old.find(" version=\"2\""), 12, " version=\"1\"");
        const std::string wanted = to_xml(parse_population(as_old, "old.xml"));
        const auto at = wanted.find("contentHash=\"") + 13;
        EXPECT_EQ(e.find(wanted.substr(at, 16)), std::string::npos) << e;
    }
    // Re-indenting changes no value; a tree edited by hand is still taken (evaluated again).
    std::string spaced = text;
    spaced.replace(spaced.find("<individuals"), 0, "\n\n  ");
    EXPECT_NO_THROW(parse_population(spaced, "p.xml"));
    const auto q = parse_population(edited("<tree>(sin -1)</tree>", "<tree>(sin 2)</tree>"), "p.xml");
    EXPECT_TRUE(q.population[0].edited);
    // A version 2 file without its hash is refused; version 1 (runs in flight) loads without one.
    std::string unhashed = text;
    const auto h = unhashed.find(" contentHash=\"");
    unhashed.erase(h, 31);
    EXPECT_NE(error_text(unhashed).find("has no contentHash"), std::string::npos) << error_text(unhashed);
    unhashed.replace(unhashed.find(" version=\"2\""), 12, " version=\"1\"");
    EXPECT_EQ(to_xml(parse_population(unhashed, "old.xml")), text);   // read as version 1, written as version 2
}

} // namespace
} // namespace cic::io
