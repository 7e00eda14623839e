// image_compare.h, the accuracy metric, on images small enough to work out by hand: identical
// images, one pixel off, the threshold's per-channel mask, the leak, and the comparisons that
// must be reported as failures (nothing compared, different sizes).
#include <gtest/gtest.h>

#include "shows/scene/image_compare.h"

namespace haze {
namespace {

ImageRGB filled(int w, int h, glm::vec3 value) {
  ImageRGB img;
  img.width = w;
  img.height = h;
  img.pixels.assign(static_cast<size_t>(w) * h, value);
  return img;
}

TEST(ImageCompare, IdenticalImagesHaveNoError) {
  const ImageRGB ref = filled(4, 3, glm::vec3(2.0f, 1.0f, 0.5f));
  auto c = compareImages(ref, ref);
  ASSERT_TRUE(c.ok()) << c.error().str();
  EXPECT_EQ(c->meanRelError, 0.0);
  EXPECT_EQ(c->maxRelError, 0.0);
  EXPECT_EQ(c->values, 36u);  // every channel of the 12 pixels is above 1 % of 2
  EXPECT_EQ(c->referenceMax, 2.0f);
  EXPECT_EQ(c->leak, 0.0);
}

TEST(ImageCompare, OnePixelTenPercentOffAmongN) {
  constexpr int kW = 8, kH = 5, kN = kW * kH;
  const ImageRGB ref = filled(kW, kH, glm::vec3(1.0f));
  ImageRGB actual = ref;
  actual.at(3, 2) = glm::vec3(1.1f);
  auto c = compareImages(actual, ref);
  ASSERT_TRUE(c.ok()) << c.error().str();
  // Three values off by 10 % among 3N.
  EXPECT_NEAR(c->meanRelError, 0.1 / kN, 1e-7);
  EXPECT_NEAR(c->maxRelError, 0.1, 1e-6);
  EXPECT_EQ(c->values, 3u * kN);
  // The relative error is symmetric in sign.
  actual.at(3, 2) = glm::vec3(0.9f);
  EXPECT_NEAR(compareImages(actual, ref)->meanRelError, 0.1 / kN, 1e-7);
}

TEST(ImageCompare, ThresholdMasksEachChannelOnTheReferenceMaximum) {
  ImageRGB ref = filled(2, 1, glm::vec3(0.0f));
  ref.at(0, 0) = glm::vec3(100.0f, 0.5f, 0.0f);  // red counts; green is under 1 % of 100
  ref.at(1, 0) = glm::vec3(0.0f, 0.0f, 2.0f);    // blue counts
  ImageRGB actual = ref;
  actual.at(0, 0).r = 110.0f;  // 10 % on a counted value
  actual.at(0, 0).g = 1.5f;    // off by 1 where the reference is dark: leak, not error
  auto c = compareImages(actual, ref);
  ASSERT_TRUE(c.ok()) << c.error().str();
  EXPECT_EQ(c->values, 2u);
  EXPECT_NEAR(c->meanRelError, 0.05, 1e-6);
  EXPECT_EQ(c->referenceMax, 100.0f);
  // |1.5 - 0.5| over the four dark values, over the maximum 100.
  EXPECT_NEAR(c->leak, 1.0 / 4.0 / 100.0, 1e-9);
  // A lower threshold lets the green value in: (0.1 + 2 + 0) / 3.
  auto low = compareImages(actual, ref, 0.001f);
  ASSERT_TRUE(low.ok()) << low.error().str();
  EXPECT_EQ(low->values, 3u);
  EXPECT_NEAR(low->meanRelError, 2.1 / 3.0, 1e-6);
}

TEST(ImageCompare, DarkReferenceComparesNothingAndFails) {
  const ImageRGB dark = filled(4, 4, glm::vec3(0.0f));
  const ImageRGB lit = filled(4, 4, glm::vec3(1.0f));
  auto c = compareImages(lit, dark);
  ASSERT_FALSE(c.ok()) << "a mean over no values must not read as a match";
  EXPECT_NE(c.error().message.find("nothing was compared"), std::string::npos) << c.error().message;
}

TEST(ImageCompare, DifferentSizesFail) {
  auto c = compareImages(filled(4, 3, glm::vec3(1.0f)), filled(3, 4, glm::vec3(1.0f)));
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.error().message.find("4x3"), std::string::npos) << c.error().message;
  EXPECT_NE(c.error().message.find("3x4"), std::string::npos) << c.error().message;
}

// compareBeams on L_in: one lamp pixel sets the core (above 1 % of the largest value), the 99.9th
// percentile (1.0: the lamp is under 0.1 % of the values) sets the wider mask and the dark.
TEST(CompareBeams, CoreWideAndLeakByHand) {
  ImageRGB ref = filled(200, 10, glm::vec3(0.0f));
  ImageRGB act = ref;
  ref.pixels[0] = glm::vec3(1000.0f);
  act.pixels[0] = glm::vec3(1100.0f);  // 10 % off
  for (size_t i = 1; i < 1000; ++i) {
    ref.pixels[i] = glm::vec3(1.0f);
    act.pixels[i] = glm::vec3(i < 50 ? 1.2f : 1.0f);  // 49 pixels 20 % off
  }
  for (size_t i = 1000; i < 2000; ++i) act.pixels[i] = glm::vec3(i < 1010 ? 0.5f : 0.005f);  // 10 leak
  auto c = compareBeams(act, ref);
  ASSERT_TRUE(c.ok()) << c.error().str();
  EXPECT_EQ(c->coreValues, 3u);
  EXPECT_NEAR(c->coreError, 0.1, 1e-6);
  EXPECT_EQ(c->wideValues, 3000u);
  EXPECT_NEAR(c->wideError, (3 * 0.1 + 49 * 3 * 0.2) / 3000.0, 1e-6);
  EXPECT_EQ(c->darkValues, 3000u);
  EXPECT_EQ(c->leakedValues, 30u);  // 0.005 is under 1 % of the percentile: not a leak
  EXPECT_NEAR(c->leak(), 0.01, 1e-12);
}

// A dim beam missing beside a bright one: the means barely move, the gross fraction counts it.
TEST(CompareBeams, GrossCountsValuesOffByMoreThanHalf) {
  ImageRGB ref = filled(100, 10, glm::vec3(100.0f));
  ImageRGB act = ref;
  for (size_t i = 0; i < 10; ++i) ref.pixels[i] = glm::vec3(5.0f);  // the dim beam, in the mask
  for (size_t i = 0; i < 10; ++i) act.pixels[i] = glm::vec3(0.0f);  // left out
  act.pixels[20] = glm::vec3(149.0f);                                 // 49 % off: not gross
  auto c = compareBeams(act, ref);
  ASSERT_TRUE(c.ok()) << c.error().str();
  EXPECT_EQ(c->wideValues, 3000u);
  EXPECT_EQ(c->grossValues, 30u);
  EXPECT_NEAR(c->gross(), 0.01, 1e-12);
  EXPECT_LT(c->coreError, 0.011);  // the mean: 1 % however wrong the dim beam is
}

TEST(CompareBeams, DarkReferenceOrOtherSizeIsAnError) {
  const ImageRGB dark = filled(4, 4, glm::vec3(0.0f));
  EXPECT_FALSE(compareBeams(dark, dark).ok());
  EXPECT_FALSE(compareBeams(filled(4, 4, glm::vec3(1.0f)), filled(4, 3, glm::vec3(1.0f))).ok());
}

}  // namespace
}  // namespace haze
