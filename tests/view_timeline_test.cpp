// The playback clock (view/timeline.h): speeds, reverse, loop wrap and stop at the ends,
// stepping and scrubbing clamped to the span, against the arithmetic of each case.
#include "view/timeline.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace {

using skylit::view::kPlaybackSpeeds;
using skylit::view::Timeline;

TEST(Timeline, StartsPausedAtTheStartAndPlaysAtItsSpeed) {
  Timeline t(1000.0, 1600.0);
  t.advance(10.0);
  EXPECT_EQ(t.time(), 1000.0);  // paused
  t.set_playing(true);
  t.advance(2.0);
  EXPECT_DOUBLE_EQ(t.time(), 1002.0);
  for (int k = 0; k < 4; ++k) t.faster();  // 1 → 16×
  EXPECT_EQ(t.speed(), 16.0);
  t.advance(0.5);
  EXPECT_DOUBLE_EQ(t.time(), 1010.0);
  t.toggle_reverse();
  t.advance(0.25);
  EXPECT_DOUBLE_EQ(t.time(), 1006.0);
}

TEST(Timeline, SpeedsSpanAQuarterTo256AndClamp) {
  Timeline t(0.0, 1.0);
  for (int k = 0; k < 20; ++k) t.slower();
  EXPECT_EQ(t.speed(), 0.25);
  for (int k = 0; k < 20; ++k) t.faster();
  EXPECT_EQ(t.speed(), 256.0);
  EXPECT_EQ(kPlaybackSpeeds.front(), 0.25);
}

TEST(Timeline, LoopWrapsBothWays) {
  Timeline t(0.0, 100.0);
  t.set_playing(true);
  t.set_speed_index(6);  // 16×
  t.advance(7.0);        // 112 → 12
  EXPECT_NEAR(t.time(), 12.0, 1e-9);
  t.toggle_reverse();
  t.advance(1.0);  // 12 − 16 = −4 → 96
  EXPECT_NEAR(t.time(), 96.0, 1e-9);
  EXPECT_TRUE(t.playing());
}

TEST(Timeline, WithoutLoopItStopsAtTheEndAndRestartsFromTheStart) {
  Timeline t(0.0, 100.0);
  t.set_loop(false);
  t.set_playing(true);
  t.advance(150.0);
  EXPECT_EQ(t.time(), 100.0);
  EXPECT_FALSE(t.playing());
  t.set_playing(true);
  EXPECT_EQ(t.time(), 0.0);
}

TEST(Timeline, StepsPauseAndClamp) {
  Timeline t(0.0, 10.0);
  t.set_playing(true);
  t.step_frames(3, 0.5);
  EXPECT_FALSE(t.playing());
  EXPECT_DOUBLE_EQ(t.time(), 1.5);
  t.step_seconds(-5.0);
  EXPECT_EQ(t.time(), 0.0);
  t.scrub(42.0);
  EXPECT_EQ(t.time(), 10.0);
}

TEST(Timeline, EndBeforeStartIsAnError) { EXPECT_THROW(Timeline(5.0, 4.0), std::invalid_argument); }

}  // namespace
