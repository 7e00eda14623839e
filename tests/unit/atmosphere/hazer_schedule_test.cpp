// Hazers whose output and fan change over time: the schedule's levels against their closed
// forms, the haze put out against the integral of the output level, and a fan held at a level
// against the same fan built at that speed.
#include <gtest/gtest.h>

#include <cmath>

#include "atmosphere/density_sim.h"
#include "atmosphere/hazer_schedule.h"

namespace haze {
namespace {

DensityGrid room() {
  DensityGrid g;
  g.n[0] = 24;
  g.n[1] = 12;
  g.n[2] = 24;
  g.minM = {-5, 0, -5};
  g.maxM = {5, 5, 5};
  return g;
}

DensitySpec oneHazer(float speedMps = 3.0f) {
  DensitySpec s;
  s.base = 0.5f;
  s.mixingM2ps = 0.05f;
  s.hazers.push_back({.positionM = {-4, 0.5f, 0}, .direction = {1, 0.2f, 0}, .output = 0.8f, .spreadDeg = 30, .speedMps = speedMps});
  return s;
}

TEST(HazerSchedule, LevelsAreLinearBetweenKeysAndHeldOutside) {
  HazerSchedule s;
  EXPECT_EQ(s.at(0, 5.0), (HazerLevel{1.0f, 1.0f}));  // no keys: full
  s.hold(0, {0.2f, 1.0f});
  s.fade(0, 10.0, 2.0, 4.0, {1.0f, 0.5f});  // waits until 12, arrives at 16
  EXPECT_FLOAT_EQ(s.at(0, 0.0).output, 0.2f);
  EXPECT_FLOAT_EQ(s.at(0, 11.9).output, 0.2f);
  EXPECT_FLOAT_EQ(s.at(0, 13.0).output, 0.2f + 0.8f * 0.25f);
  EXPECT_FLOAT_EQ(s.at(0, 13.0).fan, 1.0f - 0.5f * 0.25f);
  EXPECT_FLOAT_EQ(s.at(0, 100.0).output, 1.0f);
  EXPECT_TRUE(s.fansChange());
  // A GO at 14 takes the running fade over from where it is (output 0.6) to 0 at once.
  s.fade(0, 14.0, 0.0, 0.0, {0.0f, 0.5f});
  EXPECT_FLOAT_EQ(s.at(0, 13.99).output, 0.2f + 0.8f * (1.99f / 4.0f));
  EXPECT_FLOAT_EQ(s.at(0, 14.0).output, 0.6f);
  EXPECT_FLOAT_EQ(s.at(0, 14.001).output, 0.0f);
  // Another hazer is untouched.
  EXPECT_EQ(s.at(1, 13.0), (HazerLevel{1.0f, 1.0f}));
}

TEST(HazerSchedule, HazeOutEqualsTheIntegralOfTheOutputLevel) {
  // Output 0 for 10 s, then up to 1 over 20 s: by 60 s the hazer has run
  // 0.8 * (20 / 2 + 30) m^3 of haze at D = 1 (closed walls, no dissipation).
  HazerSchedule s;
  s.hold(0, {0.0f, 1.0f});
  s.fade(0, 10.0, 0.0, 20.0, {1.0f, 1.0f});
  DensitySim sim(oneHazer(), room(), s);
  EXPECT_NEAR(sim.hazeTotalAt(60.0), 0.8 * 40.0, 0.01 * 0.8 * 40.0);
  EXPECT_NEAR(sim.hazeTotalAt(10.0), 0.0, 1e-6);
  // Held at a quarter: a quarter of the full hazer's haze.
  HazerSchedule quarter;
  quarter.hold(0, {0.25f, 1.0f});
  DensitySim a(oneHazer(), room(), quarter), full(oneHazer(), room());
  EXPECT_NEAR(a.hazeTotalAt(30.0), 0.25 * full.hazeTotalAt(30.0), 1e-4 * full.hazeTotalAt(30.0));
}

TEST(HazerSchedule, AFanHeldAtALevelBlowsLikeAFanOfThatSpeed) {
  HazerSchedule half;
  half.hold(0, {1.0f, 0.5f});
  DensitySim a(oneHazer(3.0f), room(), half), b(oneHazer(1.5f), room());
  const DensityField fa = a.fieldAt(20.0), fb = b.fieldAt(20.0);
  ASSERT_EQ(fa.values.size(), fb.values.size());
  double worst = 0.0, peak = 0.0;
  for (size_t i = 0; i < fa.values.size(); ++i) {
    worst = std::max(worst, std::fabs(double(fa.values[i]) - fb.values[i]));
    peak = std::max(peak, double(fb.values[i]));
  }
  EXPECT_LT(worst, 1e-5 * peak);
  // And the fan matters: at full speed the haze lies elsewhere.
  DensitySim c(oneHazer(3.0f), room());
  const DensityField fc = c.fieldAt(20.0);
  double moved = 0.0;
  for (size_t i = 0; i < fa.values.size(); ++i) moved = std::max(moved, std::fabs(double(fa.values[i]) - fc.values[i]));
  EXPECT_GT(moved, 0.05 * peak);
}

TEST(HazerSchedule, AFanSwitchedOffLaterBlowsAsBeforeUntilThen) {
  // Until the fan fades at 15 s the field is the full fan's, step for step.
  HazerSchedule off;
  off.hold(0, {1.0f, 1.0f});
  off.fade(0, 15.0, 0.0, 5.0, {1.0f, 0.0f});
  DensitySim a(oneHazer(), room(), off), b(oneHazer(), room());
  EXPECT_EQ(a.stepS(), b.stepS());
  EXPECT_EQ(a.fieldAt(12.0).values, b.fieldAt(12.0).values);
  // After it the haze stays nearer the nozzle, and the total is the same (the fan moves haze,
  // it does not make it).
  EXPECT_NE(a.fieldAt(40.0).values, b.fieldAt(40.0).values);
  EXPECT_NEAR(a.hazeTotalAt(40.0), b.hazeTotalAt(40.0), 1e-3 * b.hazeTotalAt(40.0));
}

}  // namespace
}  // namespace haze
