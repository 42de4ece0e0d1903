// assess_gait: the dominant command frequency of known sine gaits, a held
// pose that never shakes, a body turned upside down, and bad arguments.
#include <gtest/gtest.h>

#include <stdexcept>

#include "cic/report/gait_assessment.hpp"
#include "cic/report/preset_replay.hpp"

namespace cic::report {
namespace {

ReplayItem sine_replay(const std::string& controller) {
    PresetReplay p;
    p.robot_type = 1;
    p.controller = controller;
    p.sim.sample_to = 4.0;
    return replay_preset(p, 10.0, true);
}

TEST(GaitAssessment, SineGaitsHaveTheirFrequencyAndOnlyFastOnesShake) {
    const GaitAssessment slow = assess_gait(sine_replay("sine:0.6,0.5"));
    EXPECT_NEAR(slow.dominant_hz, 0.5, 0.15);
    EXPECT_FALSE(slow.shaking);
    const GaitAssessment fast = assess_gait(sine_replay("sine:0.6,8"));
    EXPECT_NEAR(fast.dominant_hz, 8.0, 0.5);
    EXPECT_TRUE(fast.shaking);
    EXPECT_FALSE(assess_gait(sine_replay("sine:0.6,8"), 10.0).shaking);   // the bound is the caller's
    for (const GaitAssessment& a : {slow, fast}) {
        EXPECT_FALSE(a.flipped);
        EXPECT_GT(a.final_up, 0.5);
        EXPECT_GT(a.mean_height, 0.0);
        EXPECT_LE(a.min_height, a.mean_height);
    }
}

TEST(GaitAssessment, HeldPoseHasNoFrequency) {
    const GaitAssessment held = assess_gait(sine_replay("constant:0.3"));
    EXPECT_EQ(held.dominant_hz, 0.0);
    EXPECT_FALSE(held.shaking);
}

TEST(GaitAssessment, UpsideDownAtTheEndIsFlipped) {
    ReplayItem item;
    for (int s = 0; s < 3; ++s) item.trace.push_back({0.1 * s, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0, 0.05}, {}});
    item.recording.frames = {{sim::Pose{}}, {sim::Pose{{0, 0, 0.05}, {0, 1, 0, 0}}}};   // 180 degrees about x
    const GaitAssessment a = assess_gait(item);
    EXPECT_NEAR(a.final_up, -1.0, 1e-12);
    EXPECT_TRUE(a.flipped);
    EXPECT_EQ(a.verdict, "flipped");
    item.recording.frames.back().front().quat = {0.86602540378443865, 0.5, 0, 0};   // 60 degrees: tilted, not flipped
    EXPECT_NEAR(assess_gait(item).final_up, 0.5, 1e-12);
    EXPECT_FALSE(assess_gait(item).flipped);
}

// One verdict per gait, eq. 7.1 split into its terms, and a duty factor per foot.
TEST(GaitAssessment, EachGaitGetsAVerdictItsTermsAndItsFeetsDutyFactors) {
    const GaitAssessment slow = assess_gait(sine_replay("sine:0.6,0.5"));
    EXPECT_EQ(slow.verdict, "walking");
    EXPECT_DOUBLE_EQ(slow.distance + slow.elevation, slow.raw_fitness);
    ASSERT_EQ(slow.foot_names.size(), 4u);   // R1's four feet, the ends of its legs
    EXPECT_EQ(slow.foot_names.front(), "leg+x-y.2");
    double touched = 0;
    for (double d : slow.duty_factors) {
        EXPECT_GE(d, 0.0);
        EXPECT_LE(d, 1.0);
        touched += d;
    }
    EXPECT_GT(touched, 0.5) << "a walking robot stands on its feet";
    EXPECT_EQ(assess_gait(sine_replay("sine:0.6,8")).verdict, "shaking");
    const GaitAssessment held = assess_gait(sine_replay("constant:0.3"));   // no stepping
    EXPECT_EQ(held.verdict, held.elevation >= held.distance ? "standing up" : "sliding");
    // A held pose that lifts the body scores by elevation alone: standing up, not "shaking 0".
    ReplayItem stand = sine_replay("constant:0.3");
    stand.distance = 0.1;
    stand.elevation = 0.6;
    EXPECT_EQ(assess_gait(stand).verdict, "standing up");
    stand.distance = 2.0;
    EXPECT_EQ(assess_gait(stand).verdict, "sliding");
}

TEST(GaitAssessment, BadArgumentsThrow) {
    ReplayItem empty;
    EXPECT_THROW(assess_gait(empty), std::invalid_argument);
    const ReplayItem ok = sine_replay("sine:0.6,0.5");
    EXPECT_THROW(assess_gait(ok, 0.0), std::invalid_argument);
    ReplayItem no_frames = ok;
    no_frames.recording.frames.clear();
    EXPECT_THROW(assess_gait(no_frames), std::invalid_argument);
}

} // namespace
} // namespace cic::report
