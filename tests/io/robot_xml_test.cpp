// Robot files: the shipped presets equal sim::preset, round trips, clear
// errors with file and line, and user-made robots (snake, cross) that run.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "cic/core/error.hpp"
#include "cic/io/robot_xml.hpp"
#include "cic/sim/evaluate.hpp"
#include "cic/sim/layout.hpp"

using namespace cic;
using namespace cic::sim;

namespace {

const std::filesystem::path kRobots = std::filesystem::path(CIC_SOURCE_DIR) / "settings" / "robots";

void expect_same(const RobotSpec& a, const RobotSpec& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.centre, b.centre);
    EXPECT_EQ(a.preferred, b.preferred);
    ASSERT_EQ(a.modules.size(), b.modules.size());
    for (std::size_t i = 0; i < a.modules.size(); ++i) {
        EXPECT_EQ(a.modules[i].cell, b.modules[i].cell) << i;
        EXPECT_EQ(a.modules[i].axis, b.modules[i].axis) << i;
        EXPECT_EQ(a.modules[i].attach, b.modules[i].attach) << i;
        EXPECT_EQ(a.modules[i].name, b.modules[i].name) << i;
    }
}

// The error text of parsing `xml`, or "" when it parses.
std::string error_of(const std::string& xml) {
    try {
        io::parse_robot_xml(xml, "bad.xml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

const std::string kHeader = "<robot name=\"t\" centre=\"a\" preferred=\"x\">\n";

} // namespace

TEST(RobotXml, ShippedPresetsEqualThePresets) {
    for (int type : {0, 1, 2})
        for (bool middle : {false, true}) {
            const auto file = kRobots / ("r" + std::to_string(type) + (middle ? "_6legs" : "") + ".xml");
            SCOPED_TRACE(file.string());
            expect_same(io::read_robot_file(file), preset(type, middle));
            expect_same(io::load_robot("R" + std::to_string(type), middle), preset(type, middle));
        }
    expect_same(io::load_robot((kRobots / "r1.xml").string(), true), preset(1, false));
}

TEST(RobotXml, RoundTrips) {
    for (const char* f : {"snake.xml", "cross.xml", "r2_6legs.xml"}) {
        const RobotSpec r = io::read_robot_file(kRobots / f);
        expect_same(io::parse_robot_xml(io::robot_to_xml(r)), r);
    }
    const auto tmp = std::filesystem::temp_directory_path() / "cic_robot_xml_test.xml";
    io::write_robot_file(preset(0, true), tmp);
    expect_same(io::read_robot_file(tmp), preset(0, true));
    std::filesystem::remove(tmp);
    // A centre given by index, modules without names.
    const RobotSpec r = io::parse_robot_xml(
        "<robot centre=\"1\" preferred=\"y\"><module x=\"1\" y=\"0\" z=\"0\" axis=\"z\" attach=\"-x\"/>"
        "<module x=\"0\" y=\"0\" z=\"0\" axis=\"fixed\" attach=\"none\"/></robot>");
    EXPECT_EQ(r.centre, 1);
    expect_same(io::parse_robot_xml(io::robot_to_xml(r)), r);
}

TEST(RobotXml, ErrorsNameFileAndLine) {
    const std::string a = "  <module name=\"a\" x=\"0\" y=\"0\" z=\"0\" axis=\"fixed\" attach=\"none\"/>\n";
    EXPECT_EQ(error_of(kHeader + a + "  <module name=\"b\" x=\"1\" y=\"0\" z=\"0\" axis=\"y\" attach=\"-x\"/>\n</robot>"), "");
    EXPECT_EQ(error_of(kHeader + a + "  <module name=\"b\" x=\"1\" y=\"0\" z=\"0\" axis=\"w\" attach=\"-x\"/>\n</robot>"),
              "bad.xml:3: <module> axis=\"w\": expected x, y, z or fixed");
    EXPECT_EQ(error_of(kHeader + a + "  <module name=\"b\" x=\"1\" y=\"0\" z=\"0\" axis=\"y\" attach=\"up\"/>\n</robot>")
                  .rfind("bad.xml:3: <module> attach=\"up\": expected +x", 0), 0u);
    const std::string overlap =
        error_of(kHeader + a + "\n  <module name=\"b\" x=\"0\" y=\"0\" z=\"0\" axis=\"y\" attach=\"-x\"/>\n</robot>");
    EXPECT_EQ(overlap.rfind("bad.xml:4: invalid robot: overlapping cells", 0), 0u) << overlap;
    const std::string loose =
        error_of(kHeader + a + "  <module name=\"b\" x=\"3\" y=\"0\" z=\"0\" axis=\"y\" attach=\"none\"/>\n</robot>");
    EXPECT_EQ(loose.rfind("bad.xml:3: invalid robot: disconnected modules", 0), 0u) << loose;
    const std::string gap =
        error_of(kHeader + a + "  <module name=\"b\" x=\"3\" y=\"0\" z=\"0\" axis=\"y\" attach=\"-x\"/>\n</robot>");
    EXPECT_NE(gap.find("bad.xml:3:"), std::string::npos);
    EXPECT_NE(gap.find("empty cell"), std::string::npos) << gap;
    EXPECT_EQ(error_of("<robot preferred=\"x\">\n" + a + "</robot>"),
              "bad.xml:1: no centre: <robot> needs attribute centre (a module name)");
    EXPECT_EQ(error_of("<robot centre=\"zz\" preferred=\"x\">\n" + a + "</robot>"),
              "bad.xml:1: no centre: centre=\"zz\" names no module");
    EXPECT_NE(error_of("<robot centre=\"a\" preferred=\"z\">\n" + a + "</robot>").find("preferred=\"z\" must be x or y"),
              std::string::npos);
    EXPECT_EQ(error_of(kHeader + "  <module name=\"a\" x=\"0.5\" y=\"0\" z=\"0\" axis=\"fixed\" attach=\"none\"/>\n</robot>"),
              "bad.xml:2: <module> attribute x=\"0.5\" is not an integer");
    EXPECT_EQ(error_of(kHeader + "  <module name=\"a\" y=\"0\" z=\"0\" axis=\"fixed\" attach=\"none\"/>\n</robot>"),
              "bad.xml:2: <module> needs attribute x");
    EXPECT_NE(error_of(kHeader + a + a + "</robot>").find("duplicate module name \"a\""), std::string::npos);
    EXPECT_NE(error_of(kHeader + "  <leg/>\n</robot>").find("bad.xml:2: unknown element <leg> in <robot> (allowed: module)"),
              std::string::npos);
    EXPECT_EQ(error_of("<robots/>"), "bad.xml:1: not a robot file: the root element is <robots>; a robot file's is <robot>");
    EXPECT_NE(error_of("<robot").find("bad.xml"), std::string::npos);
    EXPECT_THROW(io::read_robot_file(kRobots / "no_such_robot.xml"), InputError);
}

TEST(RobotXml, UserMadeRobotsRun) {
    SimConfig cfg;
    cfg.sample_to = 3.0;
    cfg.delayed_start = 1.0;
    struct Row { const char* file; int bodies; int joints; };
    // snake: a fixed head and 6 hinged segments in a chain -> 7 bodies, 6 hinges.
    // cross: a fixed hub and 4 arms of 2 hinged modules -> 9 bodies, 8 hinges.
    for (const Row& row : {Row{"snake.xml", 7, 6}, Row{"cross.xml", 9, 8}}) {
        const RobotSpec robot = io::read_robot_file(kRobots / row.file);
        const BodyLayout layout = make_body_layout(robot);
        EXPECT_EQ(layout.body_count, row.bodies) << row.file;
        EXPECT_EQ(layout.joints.size(), static_cast<std::size_t>(row.joints)) << row.file;
        SineController wave({{0.8, 0.5, 0.0}, {0.8, 0.5, 1.5}});
        const EvalResult r = evaluate(robot, wave, cfg);
        EXPECT_FALSE(r.failed) << row.file << ": " << r.failure;
        EXPECT_TRUE(std::isfinite(r.fitness));
        EXPECT_GT(std::fabs(r.end[0] - r.start[0]) + std::fabs(r.end[1] - r.start[1]), 1e-3) << row.file;
    }
}
