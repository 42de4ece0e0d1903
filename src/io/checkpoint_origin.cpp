// Where a checkpoint came from (checkpoint_origin.hpp).
#include "cic/io/checkpoint_origin.hpp"

#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "cic/core/error.hpp"
#include "cic/core/hash.hpp"
#include "cic/io/bodies.hpp"
#include "cic/io/experiment_types.hpp"
#include "cic/io/robot_xml.hpp"
#include "cic/io/settings_table.hpp"
#include "cic/tree/primitives.hpp"
#include "settings_values.hpp"

namespace cic::io {
namespace {

// "key=value" tokens of a section's keys that are not at their default; a
// path key stands for its file's contents (a copy elsewhere is the same).
std::string section_text(const Settings& s, const std::string& section, const std::set<std::string>& skip) {
    std::string out;
    for (const auto& k : settings_table()) {
        if (k.section != section || skip.count(k.key)) continue;
        std::string value = k.get(s);
        if (computes_as_default(k, value)) continue;
        if (k.type == ValueType::Path && !value.empty()) {
            std::ifstream in(value, std::ios::binary);
            if (in) value = "contents:" + hex16(fnv1a_64(std::string(std::istreambuf_iterator<char>(in), {})));
        }
        // A value with spaces (a list) keeps one token: its spaces become commas.
        for (char& c : value)
            if (c == ' ') c = ',';
        out += (out.empty() ? "" : " ") + k.key + "=" + value;
    }
    return out;
}

// A simulator part as written before issue 55 named Simulator.collisionSpace=1
// (sweep), which computes what the default computes: read as today's text.
std::string without_default_routes(const std::string& text) {
    std::istringstream in(text);
    std::string out;
    for (std::string tok; in >> tok;) {
        const auto eq = tok.find('=');
        const SettingKey* k = eq == std::string::npos ? nullptr : find_setting("Simulator", tok.substr(0, eq));
        if (k && !k->same_result_as_default.empty() && computes_as_default(*k, tok.substr(eq + 1))) continue;
        out += (out.empty() ? "" : " ") + tok;
    }
    return out;
}

std::string join_tokens(std::initializer_list<std::string> tokens) {
    std::string out;
    for (const auto& t : tokens)
        if (!t.empty()) out += (out.empty() ? "" : " ") + t;
    return out;
}

sim::RobotSpec robot_of(const Settings& s) {
    return s.robot.robot_file.empty() ? sim::preset(s.robot.robot_type, s.neural.middle_legs)
                                      : read_robot_file(s.robot.robot_file);
}

// key=value tokens as a map (a part's text).
std::map<std::string, std::string> tokens_of(const std::string& text) {
    std::map<std::string, std::string> out;
    std::istringstream in(text);
    for (std::string tok; in >> tok;) {
        const auto eq = tok.find('=');
        out[tok.substr(0, eq)] = eq == std::string::npos ? "" : tok.substr(eq + 1);
    }
    return out;
}

// What differs between two texts of a key=value part: "simulationTime: checkpoint 20, settings 10 (default)".
std::string token_differences(const std::string& had, const std::string& want) {
    const auto a = tokens_of(had), b = tokens_of(want);
    std::set<std::string> keys;
    for (const auto& [k, v] : a) keys.insert(k);
    for (const auto& [k, v] : b) keys.insert(k);
    std::string out;
    for (const auto& k : keys) {
        const auto ia = a.find(k), ib = b.find(k);
        const std::string va = ia == a.end() ? "(default)" : ia->second, vb = ib == b.end() ? "(default)" : ib->second;
        if (va == vb) continue;
        out += fmt::format("{}{} checkpoint {}, settings {}", out.empty() ? "" : ", ", k, va, vb);
    }
    return out;
}

// Several bodies in one fitness: the aggregate and every other body, by
// content; a growing robot: its whole schedule, each body with the share and
// the generation it takes over at (io/bodies.hpp).
void add_body_parts(CheckpointOrigin& o, const Settings& s) {
    if (several_bodies(s)) {
        std::string text = "aggregate " + find_setting("Simulator", "bodiesAggregate")->get(s) + ":";
        for (const auto& f : s.robot.extra_robot_files) text += " " + robot_origin_text(read_robot_file(f)) + ";";
        o.parts.push_back({"bodies", text});
    }
    if (grows(s)) {
        std::string text;
        for (std::size_t k = 1; k < growing_bodies(s); ++k)
            text += fmt::format("{}at {} (generation {}): {};", text.empty() ? "" : " ",
                                detail::format_double(s.robot.grow_at[k - 1]),
                                grow_generation(s, k), robot_origin_text(read_robot_file(s.robot.grow_robot_files[k - 1])));
        o.parts.push_back({"growth", text});
    }
}

} // namespace

std::string CheckpointOrigin::digest() const {
    std::string text;
    for (const auto& p : parts) text += p.name + "=" + p.text + "\n";
    return hex16(fnv1a_64(text));
}

std::string robot_origin_text(const sim::RobotSpec& robot) {
    std::string geometry;
    for (const auto& m : robot.modules)
        geometry += fmt::format("{},{},{},{},{};", m.cell.x, m.cell.y, m.cell.z, sim::to_string(m.axis),
                                sim::to_string(m.attach));
    geometry += fmt::format("centre={};preferred={}", robot.centre, sim::to_string(robot.preferred));
    const std::size_t joints = robot.actuated().size();
    return fmt::format("{} ({} module{}, {} joint{}; geometry {})", robot.name.empty() ? "robot" : robot.name,
                       robot.modules.size(), robot.modules.size() == 1 ? "" : "s", joints, joints == 1 ? "" : "s",
                       hex16(fnv1a_64(geometry)));
}

CheckpointOrigin origin_of(const Settings& s) {
    if (family_of(s) == ExperimentFamily::Symreg) return origin_of(s, sim::RobotSpec{});
    return origin_of(s, robot_of(s));
}

CheckpointOrigin origin_of(const Settings& s, const sim::RobotSpec& robot) {
    CheckpointOrigin o;
    const ExperimentFamily family = family_of(s);
    o.parts.push_back({"experiment", s.experiment.type});
    if (family != ExperimentFamily::Symreg) {
        o.parts.push_back({"robot", robot_origin_text(robot)});
        // The robot keys are in the robot's part, by content, and the other
        // bodies' in parts of their own (absent with one body).
        o.parts.push_back({"simulator", section_text(s, "Simulator", {"robotFile", "robot_type", "generatePovrayFiles",
                                                                     "extraRobotFiles", "bodiesAggregate",
                                                                     "growRobotFiles", "growAt"})});
        add_body_parts(o, s);
    }
    if (family == ExperimentFamily::Gait) {
        // The encoding: what a parameter vector means. The optimiser, its
        // population and restarts only choose which vectors are tried.
        const std::string shape = section_text(s, "Gait", {"controller", "evaluations", "optimizer", "populationSize",
                                                           "sigma0", "restarts", "restartPatience", "restartTolerance",
                                                           "restartTolX"});
        const auto controller = find_setting("Gait", "controller");
        o.parts.push_back({"controller", join_tokens({"controller=" + controller->get(s), shape})});
    } else {
        if (family == ExperimentFamily::HyperGP) {
            const auto substrate = find_setting("Neural", "substrate");
            o.parts.push_back({"controller", join_tokens({"substrate=" + substrate->get(s),
                                                          section_text(s, "Neural", {"substrate", "useMiddleLegs", "offsetSigma", "offsetRate",
                                                                                "switchPatience", "switchShare"})})});
        }
        std::string functions;
        for (auto op : s.gp.primitives.functions) functions += (functions.empty() ? "" : ",") + std::string(tree::name(op));
        // Named by their settings keys, so that a refusal names the key to change.
        o.parts.push_back({"genotype", fmt::format("terminalVariableCount={} numberOfTreesInForestGenotype={} functions={}",
                                                   s.gp.primitives.variable_count, s.gp.trees_per_genotype, functions)});
        if (family == ExperimentFamily::Symreg)
            o.parts.push_back({"dataset", section_text(s, "SymbolicRegression", {})});
    }
    if (s.map_elites.enabled)
        o.parts.push_back({"descriptor", fmt::format("descriptor={} bins={} omniRange={}",
                                                     find_setting("MapElites", "descriptor")->get(s),
                                                     find_setting("MapElites", "bins")->get(s),
                                                     find_setting("MapElites", "omniRange")->get(s))});
    return o;
}

void write_origin(xml::Node root, const CheckpointOrigin& origin) {
    auto e = root.add_element("origin");
    e.set_attribute("digest", origin.digest());
    for (const auto& p : origin.parts) e.add_child("part", p.text).set_attribute("name", p.name);
}

CheckpointOrigin read_origin(const xml::Node& element) {
    CheckpointOrigin o;
    o.line = element.line();
    std::set<std::string> names;
    for (const auto& c : element.children()) {
        if (c.name() != "part") throw c.error("unknown element <" + std::string(c.name()) + "> in <origin>; allowed: part");
        const std::string name = c.attribute("name").value_or("");
        if (name.empty()) throw c.error("<part> needs a name");
        if (!names.insert(name).second) throw c.error("<origin> names part '" + name + "' twice");
        o.parts.push_back({name, c.text()});
    }
    const std::string digest = element.attribute("digest").value_or("");
    if (digest != o.digest())
        throw element.error("<origin digest=\"" + digest + "\"> does not match its parts (" + o.digest() +
                            "; edited by hand?): the checkpoint's origin cannot be trusted");
    return o;
}

std::string check_origin(const std::optional<CheckpointOrigin>& loaded, const Settings& s, const std::string& file) {
    if (!loaded)
        return "note: " + file + " has no <origin> (written by a cic before checkpoints recorded one): its robot, "
               "simulator and controller cannot be checked against these settings; it is believed";
    const CheckpointOrigin want = origin_of(s);
    std::map<std::string, std::string> had;
    for (const auto& p : loaded->parts) had[p.name] = p.name == "simulator" ? without_default_routes(p.text) : p.text;
    std::string differences;
    auto add = [&](const std::string& d) { differences += (differences.empty() ? "" : "; ") + d; };
    std::set<std::string> seen;
    for (const auto& p : want.parts) {
        seen.insert(p.name);
        const auto it = had.find(p.name);
        if (it == had.end()) {
            add(fmt::format("{}: checkpoint (none), settings {}", p.name, p.text.empty() ? "(defaults)" : p.text));
        } else if (it->second != p.text) {
            if (p.name == "robot" || p.name == "experiment" || p.name == "bodies" || p.name == "growth")
                add(fmt::format("{}: checkpoint {}, settings {}", p.name, it->second, p.text));
            else
                add(p.name + ": " + token_differences(it->second, p.text));
        }
    }
    for (const auto& p : loaded->parts)
        if (!seen.count(p.name)) add(fmt::format("{}: checkpoint {}, settings (none)", p.name, p.text));
    if (differences.empty()) return {};
    throw InputError("the checkpoint was made for another problem than these settings give, so its fitness values "
                     "do not hold here: " + differences +
                     "; resume with the settings it was made with, or start a new run",
                     file, loaded->line);
}

} // namespace cic::io
