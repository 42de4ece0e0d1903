// The controller specs every replay command takes (simulate, view, trace, render).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "cic/core/error.hpp"
#include "cic/report/preset_replay.hpp"

namespace cic::report {
namespace {

// The commanded angles of a spec's controller for `joints` joints at time t.
std::vector<double> commands(const char* spec, double t, std::size_t joints = 3) {
    auto controller = parse_controller_spec(spec);
    controller->reset(joints);
    std::vector<double> angles(joints, 0.0), desired(joints, 0.0);
    controller->step(t, angles, desired);
    return desired;
}

TEST(ControllerSpec, SineFollowsAmplitudeFrequencyAndPhaseStep) {
    const auto d = commands("sine:0.6,0.5,1", 0.3);
    for (std::size_t j = 0; j < d.size(); ++j)
        EXPECT_DOUBLE_EQ(d[j], 0.6 * std::sin(2 * std::numbers::pi * 0.5 * 0.3 + static_cast<double>(j)));
}

TEST(ControllerSpec, SinePhaseStepDefaultsToAQuarterTurn) {
    EXPECT_EQ(commands("sine:0.6,0.5", 0.7), commands("sine:0.6,0.5,1.5707963267948966", 0.7));
}

TEST(ControllerSpec, BareWordsAreTheSameForEveryCommand) {
    // `cic simulate --controller sine` took this once on its own; view, trace and render refused it.
    for (double t : {0.0, 0.4, 1.3}) {
        EXPECT_EQ(commands("sine", t), commands("sine:0.8,0.5", t));
        EXPECT_EQ(commands("constant", t), commands("constant:0", t));
    }
    EXPECT_EQ(commands("constant:0.25", 2.0), std::vector<double>(3, 0.25));
}

TEST(ControllerSpec, BadSpecsNameTheSpecAndTheForm) {
    for (const char* bad : {"sine:", "sine:1", "sine:1,2,3,4", "sine:-1,0.5", "sine:1,0", "sine:a,b",
                            "constant:", "constant:1,2", "Sine", "sine ", "cpg", ""}) {
        try {
            parse_controller_spec(bad);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(std::string("'") + bad + "'"), std::string::npos) << e.what();
        }
    }
}

} // namespace
} // namespace cic::report
