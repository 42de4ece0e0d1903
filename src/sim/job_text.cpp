// Text forms for worker jobs (see job_text.hpp).
#include "cic/sim/job_text.hpp"
#include "cic/sim/cpg.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace cic::sim {

namespace {

[[noreturn]] void bad(const std::string& what) {
    throw std::invalid_argument("job text: " + what);
}

std::string expect_word(std::istream& in, std::string_view word) {
    std::string w;
    if (!(in >> w) || w != word) bad("expected '" + std::string(word) + "', got '" + w + "'");
    return w;
}

double read_double(std::istream& in) {
    std::string w;
    if (!(in >> w)) bad("expected a number");
    return parse_hexfloat(w);
}

long read_int(std::istream& in) {
    long v = 0;
    if (!(in >> v)) bad("expected an integer");
    return v;
}

} // namespace

std::string hexfloat(double v) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    if (std::isnan(v)) return "nan";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", v);
    return buf;
}

double parse_hexfloat(const std::string& s) {
    if (s == "inf") return std::numeric_limits<double>::infinity();
    if (s == "-inf") return -std::numeric_limits<double>::infinity();
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size()) bad("not a number: '" + s + "'");
    return v;
}

void write_robot_text(std::ostream& out, const RobotSpec& r) {
    auto one_line = [](const std::string& s) {
        if (s.find('\n') != std::string::npos) bad("a robot or module name spans lines: '" + s + "'");
    };
    one_line(r.name);
    for (const Module& m : r.modules) one_line(m.name);
    out << "robot " << r.modules.size() << ' ' << r.centre << ' ' << to_string(r.preferred) << ' '
        << r.name << '\n';
    for (const Module& m : r.modules)
        out << "module " << m.cell.x << ' ' << m.cell.y << ' ' << m.cell.z << ' ' << to_string(m.axis)
            << ' ' << to_string(m.attach) << ' ' << m.name << '\n';
}

RobotSpec read_robot_text(std::istream& in) {
    RobotSpec r;
    expect_word(in, "robot");
    const long n = read_int(in);
    if (n < 0 || n > 1000000) bad("bad module count");
    r.centre = static_cast<int>(read_int(in));
    std::string w;
    in >> w;
    auto pref = axis_from_name(w);
    if (!pref) bad("bad preferred axis '" + w + "'");
    r.preferred = *pref;
    if (in.peek() == ' ') in.get();
    std::getline(in, r.name);
    for (long i = 0; i < n; ++i) {
        expect_word(in, "module");
        Module m;
        m.cell.x = static_cast<int>(read_int(in));
        m.cell.y = static_cast<int>(read_int(in));
        m.cell.z = static_cast<int>(read_int(in));
        std::string a, d;
        in >> a >> d;
        auto axis = axis_from_name(a);
        auto dir = dir_from_name(d);
        if (!axis || !dir) bad("bad module axis or attach '" + a + "' '" + d + "'");
        m.axis = *axis;
        m.attach = *dir;
        if (in.peek() == ' ') in.get();
        std::getline(in, m.name);
        r.modules.push_back(m);
    }
    return r;
}

void write_config_text(std::ostream& out, const SimConfig& cfg) {
    out << "config\n";
    for_each_field(cfg, [&](const FieldSpec& f, const auto& v) {
        const std::string_view name = f.name;
        if constexpr (std::is_same_v<std::decay_t<decltype(v)>, double>)
            out << name << ' ' << hexfloat(v) << '\n';
        else
            out << name << ' ' << v << '\n';
    });
    out << "end\n";
}

SimConfig read_config_text(std::istream& in) {
    SimConfig c;
    expect_word(in, "config");
    for_each_field(c, [&](const FieldSpec& f, auto& v) {
        expect_word(in, f.name);
        if constexpr (std::is_same_v<std::decay_t<decltype(v)>, double>)
            v = read_double(in);
        else
            v = static_cast<std::decay_t<decltype(v)>>(read_int(in));
    });
    expect_word(in, "end");
    return c;
}

std::string format_eval_reply(const EvalReply& r) {
    std::ostringstream out;
    out << "fitness " << hexfloat(r.fitness) << '\n';
    if (!r.descriptor.empty()) {   // only when asked: the plain reply is unchanged
        out << "descriptor " << r.descriptor.size();
        for (double v : r.descriptor) out << ' ' << hexfloat(v);
        out << '\n';
    }
    out << "walk " << hexfloat(r.distance) << ' ' << hexfloat(r.elevation) << '\n';
    out << "failed " << (r.failed ? 1 : 0) << '\n' << r.failure;
    return out.str();
}

EvalReply reply_of(const RobotSpec& robot, const EvalResult& r, std::vector<double> descriptor) {
    EvalReply reply{r.fitness, r.failed ? std::vector<double>{} : std::move(descriptor), r.failed, r.failure};
    if (!r.failed) std::tie(reply.distance, reply.elevation) = walk_terms(robot, r);
    return reply;
}

EvalReply reply_of(const JobResult& result, double failure_fitness) {
    if (result.ok) return parse_eval_reply(result.output);
    EvalReply failed;
    failed.fitness = failure_fitness;
    failed.failed = true;
    failed.failure = "worker: " + result.error;
    return failed;
}

EvalReply parse_eval_reply(const std::string& text) {
    std::istringstream in(text);
    EvalReply e;
    expect_word(in, "fitness");
    e.fitness = read_double(in);
    std::string w;
    in >> w;
    if (w == "descriptor") {
        const long n = read_int(in);
        if (n < 1 || n > 100000) bad("bad descriptor size");
        for (long i = 0; i < n; ++i) e.descriptor.push_back(read_double(in));
        in >> w;
    }
    if (w == "walk") {
        e.distance = read_double(in);
        e.elevation = read_double(in);
        in >> w;
    }
    if (w != "failed") bad("expected 'failed', got '" + w + "'");
    e.failed = read_int(in) != 0;
    in.get();
    std::getline(in, e.failure, '\0');
    return e;
}

std::string make_sine_job(const RobotSpec& robot, const SimConfig& cfg,
                          const std::vector<SineJoint>& joints) {
    std::ostringstream out;
    out << "sine\n";
    write_robot_text(out, robot);
    write_config_text(out, cfg);
    out << "joints " << joints.size() << '\n';
    for (const SineJoint& j : joints)
        out << hexfloat(j.amplitude) << ' ' << hexfloat(j.frequency) << ' ' << hexfloat(j.phase) << '\n';
    return out.str();
}

std::string run_sine_job(const std::string& body) {
    std::istringstream in(body);
    const RobotSpec robot = read_robot_text(in);
    const SimConfig cfg = read_config_text(in);
    expect_word(in, "joints");
    const long n = read_int(in);
    if (n < 1 || n > 100000) bad("bad joint count");
    std::vector<SineJoint> joints(static_cast<std::size_t>(n));
    for (SineJoint& j : joints) {
        j.amplitude = read_double(in);
        j.frequency = read_double(in);
        j.phase = read_double(in);
    }
    SineController controller(std::move(joints));
    return format_eval_reply(reply_of(robot, evaluate(robot, controller, cfg)));
}

namespace {

// The optional last line of a job: "descriptor NAME" asks for a behaviour descriptor.
void write_descriptor_request(std::ostream& out, Descriptor d) {
    if (d != Descriptor::None) out << "descriptor " << to_string(d) << "\n";
}

Descriptor read_descriptor_request(std::istream& in) {
    std::string w;
    if (!(in >> w)) return Descriptor::None;
    if (w != "descriptor") bad("expected 'descriptor' or the end of the job, got '" + w + "'");
    std::string name;
    if (!(in >> name)) bad("'descriptor' without a name");
    try {
        return descriptor_from(name);
    } catch (const std::invalid_argument& e) {
        bad(e.what());
    }
    return Descriptor::None;
}

// Evaluates and replies, with the behaviour descriptor when asked.
std::string evaluate_and_reply(const RobotSpec& robot, Controller& controller, const SimConfig& cfg, Descriptor d) {
    EvalOptions options;
    options.record_ground = needs_ground(d);
    const EvalResult r = evaluate(robot, controller, cfg, options);
    return format_eval_reply(reply_of(robot, r, r.failed ? std::vector<double>{} : descriptor_of(d, robot, r)));
}

} // namespace

std::string make_gait_job(const RobotSpec& robot, const SimConfig& cfg, const GaitSpec& gait, Descriptor descriptor) {
    std::ostringstream out;
    out << "gait\n";
    write_robot_text(out, robot);
    write_config_text(out, cfg);
    out << "frequency " << hexfloat(gait.frequency) << "\njoints " << gait.joints.size() << '\n';
    for (const GaitJoint& j : gait.joints)
        out << hexfloat(j.amplitude) << ' ' << hexfloat(j.phase) << ' ' << hexfloat(j.offset) << ' '
            << hexfloat(j.amplitude2) << ' ' << hexfloat(j.phase2) << '\n';
    write_descriptor_request(out, descriptor);
    return out.str();
}

std::string run_gait_job(const std::string& body) {
    std::istringstream in(body);
    const RobotSpec robot = read_robot_text(in);
    const SimConfig cfg = read_config_text(in);
    GaitSpec gait;
    expect_word(in, "frequency");
    gait.frequency = read_double(in);
    expect_word(in, "joints");
    const long n = read_int(in);
    if (n < 1 || n > 100000) bad("bad joint count");
    gait.joints.resize(static_cast<std::size_t>(n));
    for (GaitJoint& j : gait.joints) {
        j.amplitude = read_double(in);
        j.phase = read_double(in);
        j.offset = read_double(in);
        j.amplitude2 = read_double(in);
        j.phase2 = read_double(in);
    }
    const Descriptor descriptor = read_descriptor_request(in);
    GaitController controller(std::move(gait));
    return evaluate_and_reply(robot, controller, cfg, descriptor);
}

std::string make_cpg_job(const RobotSpec& robot, const SimConfig& cfg, const CpgSpec& cpg, Descriptor descriptor) {
    validate(cpg);
    std::ostringstream out;
    out << "cpg\n";
    write_robot_text(out, robot);
    write_config_text(out, cfg);
    out << "range " << hexfloat(cpg.range) << "\ninitial " << hexfloat(cpg.initial) << "\nstep "
        << hexfloat(cpg.control_step) << "\njoints " << cpg.self.size() << '\n';
    for (std::size_t i = 0; i < cpg.self.size(); ++i)
        out << hexfloat(cpg.self[i]) << ' ' << (cpg.feedback.empty() ? hexfloat(0.0) : hexfloat(cpg.feedback[i])) << '\n';
    out << "feedback " << (cpg.feedback.empty() ? 0 : 1) << "\nedges " << cpg.edges.size() << '\n';
    for (std::size_t k = 0; k < cpg.edges.size(); ++k)
        out << cpg.edges[k].a << ' ' << cpg.edges[k].b << ' ' << hexfloat(cpg.coupling[k]) << '\n';
    write_descriptor_request(out, descriptor);
    return out.str();
}

CpgSpec read_cpg_spec(std::istream& in) {
    CpgSpec cpg;
    expect_word(in, "range");
    cpg.range = read_double(in);
    expect_word(in, "initial");
    cpg.initial = read_double(in);
    expect_word(in, "step");
    cpg.control_step = read_double(in);
    expect_word(in, "joints");
    const long n = read_int(in);
    if (n < 1 || n > 100000) bad("bad joint count");
    std::vector<double> feedback;
    for (long i = 0; i < n; ++i) {
        cpg.self.push_back(read_double(in));
        feedback.push_back(read_double(in));
    }
    expect_word(in, "feedback");
    if (read_int(in) != 0) cpg.feedback = std::move(feedback);
    expect_word(in, "edges");
    const long e = read_int(in);
    if (e < 0 || e > n * n) bad("bad edge count");
    for (long k = 0; k < e; ++k) {
        const long a = read_int(in), b = read_int(in);
        if (a < 0 || b < 0 || a >= n || b >= n) bad("edge out of range");
        cpg.edges.push_back({static_cast<int>(a), static_cast<int>(b)});
        cpg.coupling.push_back(read_double(in));
    }
    try {
        validate(cpg);
    } catch (const std::invalid_argument& err) {
        bad(err.what());
    }
    return cpg;
}

std::string run_cpg_job(const std::string& body) {
    std::istringstream in(body);
    const RobotSpec robot = read_robot_text(in);
    const SimConfig cfg = read_config_text(in);
    CpgController controller(read_cpg_spec(in));
    const Descriptor descriptor = read_descriptor_request(in);
    return evaluate_and_reply(robot, controller, cfg, descriptor);
}

} // namespace cic::sim
