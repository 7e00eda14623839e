// The exposure meter (shows/scene/exposure.h) on known images: a dark stage with a lit deck is
// keyed on its highlights, a uniform scene on its log-average, a blackout stops at the gain
// limit, and the smoothing moves in EV with its time constant.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "shows/scene/exposure.h"

namespace haze {
namespace {

// display = L * 2^ev / 50 before the tone curve (DisplaySettings).
float displayOf(float nits, float ev) { return nits * std::exp2(ev) / kManualKeyNits; }

TEST(Exposure, DarkStageIsKeyedOnItsHighlights) {
  // 90 % near-black house, 9 % lit deck at 2000 cd/m^2, 1 % beams at 8000.
  std::vector<float> img(10000, 0.01f);
  for (int i = 0; i < 900; ++i) img[i] = 2000.0f;
  for (int i = 900; i < 1000; ++i) img[i] = 8000.0f;
  const Metering m = meterLuminance(img);
  EXPECT_NEAR(m.highlightNits, 8000.0f, 1e-3f);
  // The 99th percentile lands at the highlight target, below the shoulder's clip (3.1).
  EXPECT_NEAR(displayOf(8000.0f, m.ev), MeterSettings{}.highlightDisplay, 1e-3f);
  EXPECT_GT(displayOf(2000.0f, m.ev), 0.3f);  // the deck is well exposed, not grey mud
  // The manual EV 0 would put the deck at 40: white.
  EXPECT_GT(displayOf(2000.0f, 0.0f), 3.1f);
}

TEST(Exposure, UniformSceneIsKeyedOnItsAverage) {
  std::vector<float> img(4096, 100.0f);
  const Metering m = meterLuminance(img);
  EXPECT_NEAR(m.logAverageNits, 100.0f, 1e-2f);
  EXPECT_NEAR(displayOf(100.0f, m.ev), MeterSettings{}.averageKey, 1e-4f);
}

TEST(Exposure, LogAverageIsGeometric) {
  const std::vector<float> img = {1.0f, 100.0f};
  EXPECT_NEAR(meterLuminance(img).logAverageNits, 10.0f, 1e-4f);
}

TEST(Exposure, ExposureScalesWithTheLight) {
  std::vector<float> img(1000);
  for (size_t i = 0; i < img.size(); ++i) img[i] = 1.0f + static_cast<float>(i);
  std::vector<float> brighter = img;
  for (float& v : brighter) v *= 8.0f;
  EXPECT_NEAR(meterLuminance(img).ev - meterLuminance(brighter).ev, 3.0f, 1e-4f);
}

TEST(Exposure, BlackoutAndGarbageStopAtTheLimits) {
  MeterSettings s;
  EXPECT_EQ(meterLuminance(std::vector<float>(100, 0.0f), s).ev, s.maxEv);
  EXPECT_EQ(meterLuminance(std::vector<float>{}, s).ev, s.maxEv);
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> junk = {nan, inf, -5.0f, 100.0f};
  EXPECT_NEAR(meterLuminance(junk, s).highlightNits, 100.0f, 1e-4f);
  EXPECT_EQ(meterLuminance(std::vector<float>(10, 1e9f), s).ev, s.minEv);
}

TEST(Exposure, ChoiceAutoIsAnOffsetManualIsAbsolute) {
  EXPECT_FLOAT_EQ(exposureEvFor({.mode = ExposureMode::Auto, .ev = -1.0f}, -6.0f), -7.0f);
  EXPECT_FLOAT_EQ(exposureEvFor({.mode = ExposureMode::Manual, .ev = -1.0f}, -6.0f), -1.0f);
}

TEST(Exposure, AdaptationIsExponentialInEv) {
  EXPECT_FLOAT_EQ(adaptEv(std::numeric_limits<float>::quiet_NaN(), -5.0f, 0.016f), -5.0f);
  // One time constant covers 1 - 1/e of the way.
  EXPECT_NEAR(adaptEv(0.0f, -4.0f, 0.3f, 0.3f), -4.0f * (1.0f - std::exp(-1.0f)), 1e-5f);
  // Many small steps equal one big one: no dependence on the frame rate.
  float ev = 0.0f;
  for (int i = 0; i < 30; ++i) ev = adaptEv(ev, -4.0f, 0.01f, 0.3f);
  EXPECT_NEAR(ev, adaptEv(0.0f, -4.0f, 0.3f, 0.3f), 1e-4f);
  EXPECT_FLOAT_EQ(adaptEv(-2.0f, -4.0f, 0.0f), -2.0f);
}

}  // namespace
}  // namespace haze
