// Worker job texts: every field round-trips bit for bit; malformed text throws.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <bit>
#include <cstring>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "cic/sim/job_text.hpp"

using namespace cic;
using namespace cic::sim;

namespace {

std::uint64_t bits(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

} // namespace

TEST(JobText, RoundTripsExactly) {
    RobotSpec robot = preset(2, true);
    robot.name = "a robot with spaces";
    robot.modules[3].name = "";
    SimConfig cfg;
    cfg.friction = 0.1 + 0.2;   // not a short decimal
    cfg.step_divider = 3;
    std::stringstream s;
    write_robot_text(s, robot);
    write_config_text(s, cfg);
    const RobotSpec r2 = read_robot_text(s);
    const SimConfig c2 = read_config_text(s);
    EXPECT_EQ(r2.name, robot.name);
    EXPECT_EQ(r2.centre, robot.centre);
    EXPECT_EQ(r2.preferred, robot.preferred);
    ASSERT_EQ(r2.modules.size(), robot.modules.size());
    for (std::size_t i = 0; i < robot.modules.size(); ++i) {
        EXPECT_EQ(r2.modules[i].cell, robot.modules[i].cell);
        EXPECT_EQ(r2.modules[i].axis, robot.modules[i].axis);
        EXPECT_EQ(r2.modules[i].attach, robot.modules[i].attach);
        EXPECT_EQ(r2.modules[i].name, robot.modules[i].name);
    }
    EXPECT_EQ(bits(c2.friction), bits(cfg.friction));
    EXPECT_EQ(c2.step_divider, 3);
    EXPECT_TRUE(std::isinf(read_config_text(*std::make_unique<std::stringstream>([] {
        std::stringstream t;
        write_config_text(t, SimConfig{});
        return t.str();
    }())).friction));

    EvalResult r;
    r.fitness = 1.0 / 3.0;
    r.failed = true;
    r.failure = "physics blow-up: body 3\nsecond line";
    const EvalReply e = parse_eval_reply(format_eval_reply(reply_of(preset(1, false), r)));
    EXPECT_EQ(bits(e.fitness), bits(r.fitness));
    EXPECT_TRUE(e.failed);
    EXPECT_EQ(e.failure, r.failure);
    EXPECT_EQ(e.distance, 0.0);   // a failed evaluation walked nowhere
    // Eq. 7.1's terms travel exactly: distance along the preferred axis (y for R1), elevation.
    EvalResult walked;
    walked.start = {0.1, 0.2, 0.3};
    walked.end = {0.7, -1.0 / 3.0, 0.25};
    walked.fitness = 0.5;
    const EvalReply w = parse_eval_reply(format_eval_reply(reply_of(preset(1, false), walked)));
    EXPECT_EQ(bits(w.distance), bits(std::fabs(-1.0 / 3.0 - 0.2)));
    EXPECT_EQ(bits(w.elevation), bits(0.25 - 0.3));
    EXPECT_EQ(bits(w.fitness), bits(0.5));
    EXPECT_THROW(parse_eval_reply("fitness abc\nfailed 0\n"), std::invalid_argument);
    std::stringstream bad("robot 2 0 y x\nmodule 0 0 0 fixed none a\nmodule 1 0 0 w -x b\n");
    EXPECT_THROW(read_robot_text(bad), std::invalid_argument);
}

// Every SimConfig field reaches the worker: change each one from its default
// and the text read back holds the change (sim::for_each_field drives both sides).
TEST(JobText, EveryConfigFieldTravels) {
    const SimConfig defaults;
    int fields = 0;
    for_each_field(defaults, [&](const FieldSpec& spec, const auto& member) {
        using T = std::decay_t<decltype(member)>;
        SimConfig changed;
        for_each_field(changed, [&](const FieldSpec& f, auto& m) {
            if constexpr (std::is_same_v<std::decay_t<decltype(m)>, T>)
                if (f.name == spec.name) {
                    if constexpr (std::is_same_v<T, bool>) m = !m;
                    else if constexpr (std::is_same_v<T, int>) m = m + 1;
                    else m = std::isinf(m) ? 0.7 : m * 0.5 + 0.1;
                }
        });
        std::stringstream text;
        write_config_text(text, changed);
        EXPECT_NE(text.str().find(std::string(spec.name) + " "), std::string::npos) << spec.name;
        const SimConfig back = read_config_text(text);
        int differing = 0;
        for_each_field(back, [&](const FieldSpec& f, const auto& b) {
            for_each_field(changed, [&](const FieldSpec& g, const auto& c) {
                if constexpr (std::is_same_v<std::decay_t<decltype(b)>, std::decay_t<decltype(c)>>)
                    if (f.name == g.name) {
                        if constexpr (std::is_same_v<std::decay_t<decltype(b)>, double>) {
                            EXPECT_EQ(bits(b), bits(c)) << f.name;
                        } else {
                            EXPECT_EQ(b, c) << f.name;
                        }
                    }
            });
            for_each_field(defaults, [&](const FieldSpec& g, const auto& d) {
                if constexpr (std::is_same_v<std::decay_t<decltype(b)>, std::decay_t<decltype(d)>>)
                    if (f.name == g.name && !(b == d)) ++differing;
            });
        });
        EXPECT_EQ(differing, 1) << spec.name;
        ++fields;
    });
    EXPECT_EQ(fields, 21);
    std::stringstream truncated("config\nsample_from 0x0p+0\n");
    EXPECT_THROW(read_config_text(truncated), std::invalid_argument);
}

namespace cic::sim {
namespace {

// The duty-factor descriptor of MAP-Elites travels with the reply when a job
// asks for it: the same values as an evaluation in this process, the same
// fitness bits as the plain job, and the plain reply unchanged.
TEST(JobText, AGaitJobAsksForEachFootsDutyFactor) {
    const RobotSpec robot = preset(1, false);
    SimConfig cfg;
    cfg.sample_to = 3.0;
    cfg.delayed_start = 0.5;
    GaitSpec gait;
    gait.frequency = 1.0;
    for (std::size_t j = 0; j < robot.actuated().size(); ++j) gait.joints.push_back({0.6, 0.5 * static_cast<double>(j), 0.1, 0, 0});
    const std::string plain = make_gait_job(robot, cfg, gait), duty = make_gait_job(robot, cfg, gait, Descriptor::DutyFactor);
    EXPECT_EQ(duty.substr(0, plain.size()), plain);
    EXPECT_EQ(duty.substr(plain.size()), "descriptor duty-factor\n");
    const EvalReply a = parse_eval_reply(run_gait_job(plain.substr(5)));
    const EvalReply b = parse_eval_reply(run_gait_job(duty.substr(5)));
    EXPECT_TRUE(a.descriptor.empty());
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a.fitness), std::bit_cast<std::uint64_t>(b.fitness));
    GaitController controller(gait);
    EvalOptions opt;
    opt.record_ground = true;
    EXPECT_EQ(b.descriptor, duty_factors(robot, evaluate(robot, controller, cfg, opt)));
    ASSERT_EQ(b.descriptor.size(), 4u);   // R1's four feet
    // Round trip with a failure text, and a malformed descriptor refused.
    const EvalReply c = parse_eval_reply(format_eval_reply(EvalReply{0.5, {0.25, 1.0}, true, "blow-up\nline 2"}));
    EXPECT_EQ(c.descriptor, (std::vector<double>{0.25, 1.0}));
    EXPECT_EQ(c.failure, "blow-up\nline 2");
    EXPECT_THROW(parse_eval_reply("fitness 0x1p+0\ndescriptor 0\nfailed 0\n"), std::invalid_argument);
    // The omni descriptor: where the centre went, on x and y.
    const std::string omni = make_gait_job(robot, cfg, gait, Descriptor::Omni);
    EXPECT_EQ(omni.substr(plain.size()), "descriptor omni\n");
    const EvalReply d = parse_eval_reply(run_gait_job(omni.substr(5)));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a.fitness), std::bit_cast<std::uint64_t>(d.fitness));
    const EvalResult plain_result = evaluate(robot, controller, cfg);
    EXPECT_EQ(d.descriptor, (std::vector<double>{plain_result.end[0] - plain_result.start[0],
                                                 plain_result.end[1] - plain_result.start[1]}));
    // An unknown descriptor is refused by name.
    EXPECT_THROW(run_gait_job(plain.substr(5) + "descriptor speed\n"), std::invalid_argument);
    EXPECT_THROW(run_gait_job(plain.substr(5) + "duty 1\n"), std::invalid_argument);
    EXPECT_THROW(run_gait_job(plain.substr(5) + "extra 1\n"), std::invalid_argument);
}

} // namespace
} // namespace cic::sim

// A job's reply as every evaluator scores it: the worker's when it ran, else a
// failed evaluation with the failure fitness and why.
TEST(JobText, ReplyOfAJobThatRanOrNot) {
    cic::JobResult ran;
    ran.ok = true;
    ran.output = cic::sim::format_eval_reply({2.5, {0.25, 0.75}, false, "", 2.0, 0.5});
    const cic::sim::EvalReply a = cic::sim::reply_of(ran, -1000);
    EXPECT_EQ(a.fitness, 2.5);
    EXPECT_FALSE(a.failed);
    EXPECT_EQ(a.descriptor, (std::vector<double>{0.25, 0.75}));
    cic::JobResult lost;
    lost.error = "worker hung twice";
    const cic::sim::EvalReply b = cic::sim::reply_of(lost, -1000);
    EXPECT_EQ(b.fitness, -1000);
    EXPECT_TRUE(b.failed);
    EXPECT_EQ(b.failure, "worker: worker hung twice");
    EXPECT_TRUE(b.descriptor.empty());
}
