// The viewer's key bindings and clock, without a window.
#include <gtest/gtest.h>

#include <stdexcept>

#include "playback.hpp"   // private to viz: tests/CMakeLists.txt adds src/viz

namespace {

using cic::viz::Playback;

TEST(Playback, RejectsBadArguments) {
    EXPECT_THROW(Playback(0, 1.0), std::invalid_argument);
    EXPECT_THROW(Playback(1, 0.0), std::invalid_argument);
    EXPECT_THROW(Playback(1, 32.0), std::invalid_argument);
}

TEST(Playback, AdvancesAtItsSpeedAndStopsAtTheEnd) {
    Playback p(1, 1.0);
    p.advance(0.5, 10.0);
    EXPECT_DOUBLE_EQ(p.time(), 0.5);
    ASSERT_TRUE(p.press('+'));
    p.advance(0.5, 10.0);
    EXPECT_DOUBLE_EQ(p.time(), 1.5);
    p.advance(100.0, 10.0);
    EXPECT_DOUBLE_EQ(p.time(), 10.0);   // the last frame stays
}

TEST(Playback, SpaceTogglesPause) {
    Playback p(1, 1.0);
    p.press(' ');
    EXPECT_TRUE(p.paused());
    p.advance(1.0, 10.0);
    EXPECT_DOUBLE_EQ(p.time(), 0.0);
    p.press(' ');
    p.advance(1.0, 10.0);
    EXPECT_DOUBLE_EQ(p.time(), 1.0);
}

TEST(Playback, RestartGoesBackToTheStart) {
    Playback p(1, 1.0);
    p.advance(3.0, 10.0);
    p.press('r');
    EXPECT_DOUBLE_EQ(p.time(), 0.0);
}

TEST(Playback, SpeedDoublesAndHalvesWithinItsBounds) {
    Playback p(1, 1.0);
    for (int i = 0; i < 10; ++i) p.press('+');
    EXPECT_DOUBLE_EQ(p.speed(), Playback::kMaxSpeed);
    p.press('-');
    EXPECT_DOUBLE_EQ(p.speed(), Playback::kMaxSpeed / 2);
    for (int i = 0; i < 20; ++i) p.press('-');
    EXPECT_DOUBLE_EQ(p.speed(), Playback::kMinSpeed);
    EXPECT_TRUE(p.press('='));   // + without shift
    EXPECT_DOUBLE_EQ(p.speed(), Playback::kMinSpeed * 2);
}

TEST(Playback, NextAndPreviousWrapAndStartTheEntryOver) {
    Playback p(3, 1.0);
    p.advance(2.0, 10.0);
    p.press('n');
    EXPECT_EQ(p.entry(), 1);
    EXPECT_DOUBLE_EQ(p.time(), 0.0);
    p.press('n');
    p.press('n');
    EXPECT_EQ(p.entry(), 0);
    p.press('p');
    EXPECT_EQ(p.entry(), 2);
}

TEST(Playback, OtherKeysAreLeftToTheWindow) {
    Playback p(2, 1.0);
    EXPECT_FALSE(p.press('x'));
    EXPECT_FALSE(p.press(27));   // Esc closes the window
    EXPECT_EQ(p.entry(), 0);
    EXPECT_FALSE(p.paused());
}

TEST(Playback, TTogglesTheTrailAndCSwitchesTheCamera) {
    Playback p(1, 1.0);
    EXPECT_TRUE(p.trail());
    EXPECT_FALSE(p.fixed_camera());
    EXPECT_TRUE(p.press('t'));
    EXPECT_FALSE(p.trail());
    EXPECT_TRUE(p.press('c'));
    EXPECT_TRUE(p.fixed_camera());
    p.set_view(true, false);
    EXPECT_TRUE(p.trail());
    EXPECT_FALSE(p.fixed_camera());
}

} // namespace
