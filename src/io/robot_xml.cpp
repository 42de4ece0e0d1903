// Reading and writing robot files (format in robot_xml.hpp and docs/simulator.md).
#include "cic/io/robot_xml.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <map>

#include "cic/core/error.hpp"
#include "cic/io/strict_xml.hpp"
#include "cic/io/xml.hpp"

namespace cic::io {

namespace {

int int_attribute(const xml::Node& n, const char* attr) {
    auto v = n.attribute(attr);
    if (!v) throw n.error(std::string("<module> needs attribute ") + attr);
    const std::string s = xml::trim(*v);
    int out = 0;
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    if (ec != std::errc() || p != s.data() + s.size() || s.empty())
        throw n.error(std::string("<module> attribute ") + attr + "=\"" + *v + "\" is not an integer");
    return out;
}

std::string required(const xml::Node& n, const char* attr, const char* allowed) {
    auto v = n.attribute(attr);
    if (!v) throw n.error("<" + std::string(n.name()) + "> needs attribute " + attr + " (" + allowed + ")");
    return *v;
}

// The document has passed the strict reader (its root is <robot>, it holds only
// <module> elements and only known attributes); these are the robot's own rules.
sim::RobotSpec read_robot(const xml::Document& doc) {
    const xml::Node root = doc.root();
    sim::RobotSpec r;
    r.name = root.attribute("name").value_or("");
    const std::string pref = xml::trim(required(root, "preferred", "x or y"));
    auto axis = sim::axis_from_name(pref);
    if (!axis || (*axis != sim::Axis::X && *axis != sim::Axis::Y))
        throw root.error("<robot> attribute preferred=\"" + pref + "\" must be x or y");
    r.preferred = *axis;

    std::vector<int> lines;
    std::map<std::string, int> by_name;
    for (const xml::Node& n : root.children()) {
        sim::Module m;
        m.name = n.attribute("name").value_or("");
        m.cell = {int_attribute(n, "x"), int_attribute(n, "y"), int_attribute(n, "z")};
        const std::string a = xml::trim(required(n, "axis", "x, y, z or fixed"));
        auto ax = sim::axis_from_name(a);
        if (!ax) throw n.error("<module> axis=\"" + a + "\": expected x, y, z or fixed");
        m.axis = *ax;
        const std::string d = xml::trim(required(n, "attach", "+x, -x, +y, -y, +z, -z or none"));
        auto dir = sim::dir_from_name(d);
        if (!dir) throw n.error("<module> attach=\"" + d + "\": expected +x, -x, +y, -y, +z, -z or none");
        m.attach = *dir;
        if (!m.name.empty() && !by_name.emplace(m.name, static_cast<int>(r.modules.size())).second)
            throw n.error("duplicate module name \"" + m.name + "\"");
        r.modules.push_back(m);
        lines.push_back(n.line());
    }

    auto centre = root.attribute("centre");
    if (!centre) throw root.error("no centre: <robot> needs attribute centre (a module name)");
    const std::string c = xml::trim(*centre);
    if (auto it = by_name.find(c); it != by_name.end()) {
        r.centre = it->second;
    } else {
        int idx = -1;
        auto [p, ec] = std::from_chars(c.data(), c.data() + c.size(), idx);
        if (ec != std::errc() || p != c.data() + c.size() || idx < 0 ||
            idx >= static_cast<int>(r.modules.size()))
            throw root.error("no centre: centre=\"" + c + "\" names no module");
        r.centre = idx;
    }

    // Every experiment drives hinges; a robot of fixed modules only is a mistake,
    // named here at its file's line rather than later by the experiment.
    if (std::none_of(r.modules.begin(), r.modules.end(), [](const sim::Module& m) { return m.axis != sim::Axis::Fixed; }))
        throw root.error("invalid robot: every module is fixed; give at least one module a hinge (axis x, y or z)");
    if (auto problem = r.find_problem()) {
        const bool at_module = problem->module >= 0 && problem->module < static_cast<int>(lines.size());
        throw InputError("invalid robot: " + problem->message, doc.file(),
                         at_module ? lines[static_cast<std::size_t>(problem->module)] : root.line());
    }
    return r;
}

// What robot_to_xml writes as centre="...", so that read_robot finds the same
// module again. read_robot trims the attribute, looks it up among the module
// names first and only then reads it as an index. So a name is written only
// when it has no surrounding whitespace (" a" would come back as "a" and match
// nothing), and an index gets leading zeros while its digits spell another
// module's name ("0" when a module is named "0"). Both were round-trip
// failures of the fuzz_robot check (fuzz/fuzz_checks.hpp); the reproducers are
// in tests/io/fuzz_regression_test.cpp.
std::string centre_reference(const sim::RobotSpec& robot) {
    const std::string& name = robot.modules[static_cast<std::size_t>(robot.centre)].name;
    if (!name.empty() && xml::trim(name) == name) return name;
    auto is_a_name = [&](const std::string& s) {
        return std::any_of(robot.modules.begin(), robot.modules.end(), [&](const sim::Module& m) { return m.name == s; });
    };
    std::string ref = std::to_string(robot.centre);
    while (is_a_name(ref)) ref.insert(0, "0");
    return ref;
}

} // namespace

sim::RobotSpec read_robot_file(const std::filesystem::path& path) {
    return xml::load_strict(path, xml::robot_format(), read_robot);
}

sim::RobotSpec parse_robot_xml(std::string_view text, const std::string& name) {
    return xml::read_strict(text, name, xml::robot_format(), read_robot);
}

std::string robot_to_xml(const sim::RobotSpec& robot) {
    robot.validate();
    xml::Document doc = xml::Document::create("robot");
    xml::Node root = doc.root();
    root.set_attribute("name", robot.name);
    root.set_attribute("centre", centre_reference(robot));
    root.set_attribute("preferred", sim::to_string(robot.preferred));
    for (const sim::Module& m : robot.modules) {
        xml::Node n = root.add_element("module");
        if (!m.name.empty()) n.set_attribute("name", m.name);
        n.set_attribute("x", std::to_string(m.cell.x));
        n.set_attribute("y", std::to_string(m.cell.y));
        n.set_attribute("z", std::to_string(m.cell.z));
        n.set_attribute("axis", sim::to_string(m.axis));
        n.set_attribute("attach", sim::to_string(m.attach));
    }
    return doc.to_string();
}

void write_robot_file(const sim::RobotSpec& robot, const std::filesystem::path& path) {
    xml::write_file_atomically(path, robot_to_xml(robot));
}

sim::RobotSpec load_robot(const std::string& preset_or_file, bool middle_legs) {
    const std::string& s = preset_or_file;
    if (s.size() == 2 && (s[0] == 'R' || s[0] == 'r') && s[1] >= '0' && s[1] <= '2')
        return sim::preset(s[1] - '0', middle_legs);
    // Not a preset: a file. One that cannot be read at all may be a misspelt preset.
    if (!std::filesystem::is_regular_file(s))
        throw InputError("robot '" + s + "' is not R0, R1, R2 or a readable file");
    return read_robot_file(s);
}

} // namespace cic::io
