#include "shows/scene/draft_scale.h"

#include <gtest/gtest.h>

#include <cmath>

namespace haze {
namespace {

// A frame whose cost is a fixed part plus a part per pixel, as a rendered frame's.
double frameMs(float scale, double fixedMs, double fullMs) { return fixedMs + fullMs * scale * scale; }

TEST(DraftScale, NoBudgetKeepsTheFullSize) {
  DraftScale d(0.0);
  EXPECT_EQ(d.update(500.0), 1.0f);
  EXPECT_EQ(d.update(5.0), 1.0f);
  EXPECT_FALSE(d.limited());
}

TEST(DraftScale, AFastFrameKeepsTheFullSize) {
  DraftScale d(50.0);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(d.update(20.0), 1.0f);
}

TEST(DraftScale, ASlowRigSettlesWithinTheBudgetAndStaysThere) {
  // 262 ms at full size, 20 ms of it not per pixel (the Capture rig at draft 640x360).
  DraftScale d(66.0);
  float s = 1.0f;
  for (int i = 0; i < 8; ++i) s = d.update(frameMs(s, 20.0, 242.0));
  EXPECT_LE(frameMs(s, 20.0, 242.0), 66.0);
  // Not needlessly small: a step up would break the budget or leave the dead band.
  EXPECT_GT(frameMs(s + 1.0f / 16.0f, 20.0, 242.0), 66.0 * 0.7);
  // Settled: it does not flip between two scales.
  for (int i = 0; i < 20; ++i) EXPECT_EQ(d.update(frameMs(d.scale(), 20.0, 242.0)), s);
  EXPECT_FALSE(d.limited());
}

TEST(DraftScale, AFixedCostAboveTheBudgetStopsAtTheMinimumAndSaysSo) {
  DraftScale d(50.0, 0.25f);
  float s = 1.0f;
  for (int i = 0; i < 10; ++i) s = d.update(frameMs(s, 80.0, 400.0));
  EXPECT_EQ(s, 0.25f);
  EXPECT_TRUE(d.limited());
}

TEST(DraftScale, GrowsBackWhenTheRigGetsLighter) {
  DraftScale d(50.0);
  float s = 1.0f;
  for (int i = 0; i < 10; ++i) s = d.update(frameMs(s, 5.0, 400.0));
  EXPECT_LT(s, 0.5f);
  for (int i = 0; i < 10; ++i) s = d.update(frameMs(s, 5.0, 30.0));  // fewer beams on
  EXPECT_EQ(s, 1.0f);
}

TEST(DraftScale, ANewBudgetStartsFromTheFullSize) {
  DraftScale d(10.0);
  d.update(100.0);
  EXPECT_LT(d.scale(), 1.0f);
  d.setBudget(20.0);
  EXPECT_EQ(d.scale(), 1.0f);
}

}  // namespace
}  // namespace haze
