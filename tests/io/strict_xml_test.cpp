// The one strictness policy of every XML reader (io/strict_xml.hpp): settings,
// sweep, robot, population and gait checkpoint files all refuse the wrong root,
// stray text, entities, unknown elements and attributes (with a "did you
// mean"), and anything their XSD refuses; every refusal is one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include "cic/core/error.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/robot_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/io/strict_xml.hpp"
#include "support/files.hpp"

namespace cic {
namespace {

namespace fs = std::filesystem;
using namespace cic::testing;

const fs::path kSource = CIC_SOURCE_DIR;

std::string error_of(const std::function<void()>& read) {
    try {
        read();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// A reader of each format, on text, as cic reads files.
struct Reader {
    std::string name;
    std::string good;   // a valid document
    std::function<void(const std::string& text)> read;
};

std::vector<Reader> readers(const fs::path& dir) {
    const std::string robot = read_text(kSource / "settings/robots/r1.xml");
    const std::string population = read_text(kSource / "fuzz/corpus/population/symreg_hand_edited.xml");
    const std::string settings = read_text(kSource / "settings/symreg_settings.xml");
    // The sweep reader lives in the study layer (tests/study/sweep_test.cpp);
    // here the policy alone reads its format.
    const std::string sweep = "<sweep name=\"s\">\n  <base>s.xml</base>\n  <set>GP.elitism=1</set>\n"
                              "  <repeats count=\"2\" firstSeed=\"1\"/>\n</sweep>\n";
    io::GaitFile g;
    g.optimizer = "cmaes";
    g.seed = 3;
    g.dimension = 2;
    g.champion = {{0.5, -0.25}, 1.5};
    g.population = {{{0.5, -0.25}, 1.5}};
    g.history = {1.5};
    g.evaluations = 1;
    const std::string gait = io::to_xml(g);
    (void)dir;
    return {
        {"robot", robot, [](const std::string& t) { io::parse_robot_xml(t, "f.xml"); }},
        {"population", population, [](const std::string& t) { io::parse_population(t, "f.xml"); }},
        {"settings", settings, [](const std::string& t) { io::read_settings_string(t, "f.xml"); }},
        {"gait", gait, [](const std::string& t) { io::parse_gait(t, "f.xml"); }},
        {"sweep", sweep,
         [](const std::string& t) {
             io::xml::read_strict(t, "f.xml", io::xml::sweep_format(), [](const io::xml::Document&) { return 0; });
         }},
    };
}

// Inserts `what` right after the root element's start tag.
std::string inside_root(const std::string& doc, const std::string& what) {
    auto root = doc.find('<');
    while (doc.compare(root, 2, "<?") == 0 || doc.compare(root, 4, "<!--") == 0) root = doc.find('<', root + 1);
    const auto end = doc.find('>', root);
    return doc.substr(0, end + 1) + what + doc.substr(end + 1);
}

TEST(StrictXml, GoodDocumentsAreRead) {
    const auto dir = temp_dir("strict-good");
    for (const auto& r : readers(dir)) EXPECT_EQ(error_of([&] { r.read(r.good); }), "") << r.name;
    EXPECT_NE(error_of([] { io::parse_gait("<population/>", "g.xml"); })
                  .find("g.xml:1: not a gait checkpoint: the root element is <population>; a gait checkpoint's is <gaitRun>"),
              std::string::npos);
    fs::remove_all(dir);
}

TEST(StrictXml, AnotherFormatsRootIsRefused) {
    const auto dir = temp_dir("strict-root");
    for (const auto& r : readers(dir)) {
        const std::string e = error_of([&] { r.read("<gaitRun format=\"cic-gait\"/>\n"); });
        if (r.name == "gait") continue;
        EXPECT_NE(e.find(":1: not a " + r.name + " file: the root element is <gaitRun>"), std::string::npos)
            << r.name << ": " << e;
    }
    // A settings file was read whatever its root: another format's file ran as defaults.
    EXPECT_EQ(error_of([] { io::read_settings_string("<population/>", "p.xml"); }),
              "p.xml:1: not a settings file: the root element is <population>; a settings file's is <settings> or <cic>");
    fs::remove_all(dir);
}

TEST(StrictXml, StrayTextBetweenElementsIsRefused) {
    const auto dir = temp_dir("strict-text");
    for (const auto& r : readers(dir)) {
        const std::string e = error_of([&] { r.read(inside_root(r.good, "\n  oops\n")); });
        EXPECT_NE(e.find("stray text \"oops\" in <"), std::string::npos) << r.name << ": " << e;
        EXPECT_NE(e.find("f.xml:"), std::string::npos) << e;
    }
    fs::remove_all(dir);
}

TEST(StrictXml, EntitiesAreRefusedWithOneMessage) {
    const auto dir = temp_dir("strict-entities");
    const std::string message = "a DOCTYPE that declares entities or refers to a DTD is not read";
    const std::vector<std::string> doctypes = {
        "<!DOCTYPE x [<!ENTITY e SYSTEM \"/etc/hostname\">]>\n",
        "<!DOCTYPE x [<!ENTITY % p SYSTEM \"/etc/hostname\"> %p;]>\n",
        "<!DOCTYPE x [<!ENTITY e \"1\">]>\n",
        "<!DOCTYPE x SYSTEM \"cic.dtd\">\n",
    };
    for (const auto& r : readers(dir))
        for (const auto& d : doctypes) {
            std::string text = r.good;
            const auto decl = text.rfind("?>", 100);
            text.insert(decl == std::string::npos ? 0 : decl + 3, d);
            const std::string e = error_of([&] { r.read(text); });
            EXPECT_NE(e.find(message), std::string::npos) << r.name << " " << d << ": " << e;
            EXPECT_EQ(e.find('\n'), std::string::npos) << e;
        }
    // Without a DOCTYPE an entity is malformed XML already; a bare DOCTYPE is harmless.
    const std::string robot = read_text(kSource / "settings/robots/r1.xml");
    EXPECT_EQ(error_of([&] { io::parse_robot_xml("<!DOCTYPE robot>\n" + robot.substr(robot.find("<robot"))); }), "");
    fs::remove_all(dir);
}

TEST(StrictXml, UnknownAttributesAndElementsGetTheNearestName) {
    const std::string head = "<robot name=\"t\" centre=\"a\" preferred=\"x\">\n";
    const std::string a = "  <module name=\"a\" x=\"0\" y=\"0\" z=\"0\" axis=\"fixed\" attach=\"none\"/>\n";
    auto robot_error = [&](const std::string& b) {
        return error_of([&] { io::parse_robot_xml(head + a + b + "</robot>", "r.xml"); });
    };
    // Was: unknown axis "" (the misspelt attribute unnamed); mass="5" was accepted.
    EXPECT_EQ(robot_error("  <module name=\"b\" x=\"1\" y=\"0\" z=\"0\" axs=\"z\" attach=\"-x\"/>\n"),
              "r.xml:3: <module> has no attribute axs; did you mean axis? (allowed: name, x, y, z, axis, attach)");
    EXPECT_EQ(robot_error("  <module name=\"b\" x=\"1\" y=\"0\" z=\"0\" axis=\"z\" attach=\"-x\" mass=\"5\"/>\n"),
              "r.xml:3: <module> has no attribute mass (allowed: name, x, y, z, axis, attach)");
    EXPECT_EQ(robot_error("  <modul name=\"b\" x=\"1\" y=\"0\" z=\"0\" axis=\"z\" attach=\"-x\"/>\n"),
              "r.xml:3: unknown element <modul> in <robot>; did you mean module? (allowed: module)");
    EXPECT_EQ(robot_error("  <module name=\"b\" x=\"1\" y=\"0\" z=\"0\" attach=\"-x\"/>\n"),
              "r.xml:3: <module> needs attribute axis (x, y, z or fixed)");
    // An all-fixed robot is refused at its line (was: the file alone, from the experiment).
    EXPECT_EQ(robot_error(""), "r.xml:1: invalid robot: every module is fixed; give at least one module a hinge "
                               "(axis x, y or z)");
    // Settings keys keep their own messages, which name the right section.
    EXPECT_NE(error_of([] {
                  io::read_settings_string("<settings><GP><elitism n=\"3\"/></GP></settings>", "s.xml");
              }).find("s.xml:1: <GP> elitism: write the value as the element's text"),
              std::string::npos);
    EXPECT_NE(error_of([] { io::read_settings_string("<settings><GP><elitsm>1</elitsm></GP></settings>", "s.xml"); })
                  .find("unknown key <GP> elitsm; did you mean elitism?"),
              std::string::npos);
    EXPECT_NE(error_of([] { io::read_settings_string("<settings foo=\"1\"/>", "s.xml"); })
                  .find("s.xml:1: <settings> has no attribute foo"),
              std::string::npos);
}

TEST(StrictXml, TheSchemaRefusesWhatTheReaderHasNoRuleFor) {
    // The reader takes <genotype> anywhere before <individuals>; the schema
    // keeps the writer's order, so a shuffled header is refused by the net.
    std::string text = read_text(kSource / "fuzz/corpus/population/symreg_hand_edited.xml");
    const auto rng = text.find("  <rng ");
    const std::string rng_line = text.substr(rng, text.find('\n', rng) + 1 - rng);
    text.erase(rng, rng_line.size());
    text.insert(text.find("  <genotype "), rng_line);
    const std::string e = error_of([&] { io::parse_population(text, "p.xml"); });
    EXPECT_EQ(e.rfind("p.xml:3: does not match cic-population.xsd: Element 'rng': This element is not expected.", 0), 0u)
        << e;
    // Values are checked as the readers read them, trimmed.
    EXPECT_EQ(error_of([] {
                  io::read_settings_string("<settings><GP><elitism> 1 </elitism></GP></settings>", "s.xml");
              }),
              "");
}

TEST(StrictXml, EveryRefusalIsOneLine) {
    // libxml2 adds a second line to an encoding error ("Bytes: 0xE9 ...").
    const std::string e = error_of([] {
        io::read_settings_string("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<settings><Experiment><name>caf\xe9"
                                 "</name></Experiment></settings>\n",
                                 "s.xml");
    });
    EXPECT_EQ(e.rfind("s.xml:2: malformed XML: Input is not proper UTF-8", 0), 0u) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

TEST(StrictXml, ShippedFilesMatchTheirSchemas) {
    for (const auto& f : fs::directory_iterator(kSource / "settings/robots"))
        EXPECT_EQ(error_of([&] { io::read_robot_file(f.path()); }), "") << f.path();
    for (const auto& f : fs::directory_iterator(kSource / "settings")) {
        if (f.path().extension() != ".xml") continue;
        EXPECT_EQ(error_of([&] { io::read_settings(f.path()); }), "") << f.path();
    }
    // The compiled-in schemas are the shipped files, and each is a schema libxml2 takes.
    for (const auto* format : {&io::xml::sweep_format(), &io::xml::robot_format(), &io::xml::population_format(),
                               &io::xml::gait_format()}) {
        EXPECT_EQ(io::xml::schema_text(*format), read_text(kSource / "settings" / ("cic-" + format->name + ".xsd")));
        EXPECT_NO_THROW(io::xml::Schema(io::xml::schema_text(*format), format->name));
    }
}

} // namespace
} // namespace cic

namespace cic {
namespace {

// docs/robots.md: every robot example reads, and the shipped files it shows are the files.
TEST(StrictXml, DocsRobotExamplesRead) {
    const std::string doc = read_text(kSource / "docs/robots.md");
    int examples = 0;
    for (std::size_t at = doc.find("```xml\n"); at != std::string::npos; at = doc.find("```xml\n", at + 1)) {
        const std::size_t begin = at + 7, end = doc.find("```", begin);
        const std::string block = doc.substr(begin, end - begin);
        ++examples;
        EXPECT_EQ(error_of([&] { io::parse_robot_xml(block, "docs/robots.md example"); }), "") << block;
        for (const char* file : {"snake", "tripod"}) {
            const std::string shipped = read_text(kSource / "settings/robots" / (std::string(file) + ".xml"));
            if (block.find("name=\"" + std::string(file) + "\"") == std::string::npos) continue;
            EXPECT_NE(shipped.find(block), std::string::npos) << file << ".xml differs from docs/robots.md";
        }
    }
    EXPECT_EQ(examples, 4);
}

} // namespace
} // namespace cic
