#pragma once
// What each fuzz target checks, shared by the libFuzzer targets (fuzz/fuzz_*.cpp)
// and the regression test (tests/io/fuzz_regression_test.cpp), so that the
// corpora and reproducers are replayed exactly the way the fuzzers run them.
//
// Every check feeds one input to a parser:
//   - a std::exception from the parser is a correct rejection (Verdict::Rejected);
//   - a successfully parsed value must survive a cheap round trip through the
//     matching writer; if the writer or the second parse throws, or the second
//     write differs from the first, the check returns Verdict::Bug with a message.
// Crashes, sanitizer reports, leaks and hangs are not caught here: they surface
// by themselves (in the fuzzer as a crash, in the test as a dead test program).
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>

#include "cic/io/archive_xml.hpp"
#include "cic/io/gait_xml.hpp"
#include "cic/io/population_xml.hpp"
#include "cic/io/robot_xml.hpp"
#include "cic/io/settings_io.hpp"
#include "cic/tree/tree.hpp"

namespace cic::fuzz {

enum class Verdict { Rejected, Accepted, Bug };

struct Outcome {
    Verdict verdict = Verdict::Rejected;
    std::string problem;   // what went wrong when verdict == Bug
};

inline Outcome bug(std::string what) { return {Verdict::Bug, std::move(what)}; }

// What every fuzz target does with its outcome: a Bug is printed and traps, so
// that libFuzzer keeps the input as a crash; anything else returns 0.
inline int fuzz_verdict(const char* target, const Outcome& o) {
    if (o.verdict != Verdict::Bug) return 0;
    std::fprintf(stderr, "%s: %s\n", target, o.problem.c_str());
    __builtin_trap();
}

// Settings: read_settings_string (reads and validates); then
// write_settings(s) must read back, and writing that again gives the same text.
inline Outcome check_settings(std::string_view input) {
    io::Settings s;
    try {
        s = io::read_settings_string(input, "<fuzz>");
    } catch (const std::exception&) {
        return {};
    }
    try {
        const std::string first = io::write_settings(s);
        const std::string second = io::write_settings(io::read_settings_string(first, "<fuzz-roundtrip>"));
        if (first != second) return bug("settings: write -> read -> write changed the text:\n" + first + "\n---\n" + second);
    } catch (const std::exception& e) {
        return bug(std::string("settings: the written settings do not read back: ") + e.what());
    }
    return {Verdict::Accepted, {}};
}

// Population: parse_population; then to_xml must parse back and give the same text again.
inline Outcome check_population(std::string_view input) {
    io::PopulationFile p;
    try {
        p = io::parse_population(input, "<fuzz>");
    } catch (const std::exception&) {
        return {};
    }
    try {
        const std::string first = io::to_xml(p);
        const std::string second = io::to_xml(io::parse_population(first, "<fuzz-roundtrip>"));
        if (first != second) return bug("population: to_xml -> parse -> to_xml changed the text:\n" + first + "\n---\n" + second);
    } catch (const std::exception& e) {
        return bug(std::string("population: the written population does not parse back: ") + e.what());
    }
    return {Verdict::Accepted, {}};
}

// MAP-Elites archive: parse_archive; then to_xml must parse back and give the same text again.
inline Outcome check_archive(std::string_view input) {
    io::ArchiveFile a;
    try {
        a = io::parse_archive(input, "<fuzz>");
    } catch (const std::exception&) {
        return {};
    }
    try {
        const std::string first = io::to_xml(a);
        const std::string second = io::to_xml(io::parse_archive(first, "<fuzz-roundtrip>"));
        if (first != second) return bug("archive: to_xml -> parse -> to_xml changed the text:\n" + first + "\n---\n" + second);
    } catch (const std::exception& e) {
        return bug(std::string("archive: the written archive does not parse back: ") + e.what());
    }
    return {Verdict::Accepted, {}};
}

// Gait checkpoint: parse_gait; then to_xml must parse back and give the same text again.
inline Outcome check_gait(std::string_view input) {
    io::GaitFile g;
    try {
        g = io::parse_gait(input, "<fuzz>");
    } catch (const std::exception&) {
        return {};
    }
    try {
        const std::string first = io::to_xml(g);
        const std::string second = io::to_xml(io::parse_gait(first, "<fuzz-roundtrip>"));
        if (first != second) return bug("gait: to_xml -> parse -> to_xml changed the text:\n" + first + "\n---\n" + second);
    } catch (const std::exception& e) {
        return bug(std::string("gait: the written checkpoint does not parse back: ") + e.what());
    }
    return {Verdict::Accepted, {}};
}

// The primitive set of the shipped HyperGP settings (add mul atan sin gauss,
// x0..x3): a tree accepted under it must also be accepted without it, unchanged.
inline const tree::PrimitiveSet& fuzz_primitive_set() {
    static const tree::PrimitiveSet ps([] {
        tree::PrimitiveSetConfig c;
        c.functions = {tree::Op::Add, tree::Op::Mul, tree::Op::Atan, tree::Op::Sin, tree::Op::Gauss};
        c.variable_count = 4;
        return c;
    }());
    return ps;
}

// S-expression: Tree::parse; then parse(t.to_string()) == t with the same text,
// and a parse restricted to a primitive set agrees with the free one.
inline Outcome check_sexpr(std::string_view input) {
    tree::Tree t;
    try {
        t = tree::Tree::parse(input);
    } catch (const std::exception&) {
        // Whatever the free parse rejects, a restricted parse must reject too.
        try {
            tree::Tree::parse(input, &fuzz_primitive_set());
        } catch (const std::exception&) {
            return {};
        }
        return bug("sexpr: accepted with a primitive set but rejected without one");
    }
    try {
        const std::string first = t.to_string();
        const tree::Tree back = tree::Tree::parse(first);
        if (!(back == t)) return bug("sexpr: parse(to_string(t)) != t for '" + first + "'");
        if (back.to_string() != first) return bug("sexpr: to_string changed after a round trip: '" + first + "'");
        if (back.hash() != t.hash() || back.depth() != t.depth() || back.size() != t.size())
            return bug("sexpr: hash/depth/size changed after a round trip: '" + first + "'");
    } catch (const std::exception& e) {
        return bug(std::string("sexpr: the printed tree does not parse back: ") + e.what());
    }
    try {
        const tree::Tree r = tree::Tree::parse(input, &fuzz_primitive_set());
        if (!(r == t)) return bug("sexpr: the restricted parse gave another tree");
    } catch (const std::exception&) {
        // Rejected by the function set or the variable range: fine.
    }
    return {Verdict::Accepted, {}};
}

inline bool same_robot(const sim::RobotSpec& a, const sim::RobotSpec& b) {
    if (a.name != b.name || a.centre != b.centre || a.preferred != b.preferred || a.modules.size() != b.modules.size())
        return false;
    for (std::size_t i = 0; i < a.modules.size(); ++i) {
        const sim::Module &m = a.modules[i], &n = b.modules[i];
        if (!(m.cell == n.cell) || m.axis != n.axis || m.attach != n.attach || m.name != n.name) return false;
    }
    return true;
}

// Robot: parse_robot_xml (validates); then robot_to_xml must parse back to the
// same robot, and writing that again gives the same text.
inline Outcome check_robot(std::string_view input) {
    sim::RobotSpec r;
    try {
        r = io::parse_robot_xml(input, "<fuzz>");
    } catch (const std::exception&) {
        return {};
    }
    try {
        const std::string first = io::robot_to_xml(r);
        const sim::RobotSpec back = io::parse_robot_xml(first, "<fuzz-roundtrip>");
        if (!same_robot(r, back)) return bug("robot: robot_to_xml -> parse gave another robot:\n" + first);
        const std::string second = io::robot_to_xml(back);
        if (first != second) return bug("robot: robot_to_xml -> parse -> robot_to_xml changed the text:\n" + first + "\n---\n" + second);
    } catch (const std::exception& e) {
        return bug(std::string("robot: the written robot does not parse back: ") + e.what());
    }
    return {Verdict::Accepted, {}};
}

} // namespace cic::fuzz
