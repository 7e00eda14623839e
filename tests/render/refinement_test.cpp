// The refinement of half-resolution scattering (docs/rendering.md, "Refinement"): every pixel
// of a refined image is either the upsampled value (the same frame without refinement) or the
// full-resolution value (the same frame at scatter divisor 1), never a mix and never anything
// else; the refined pixels are the ones the pass counts, and they lie where the in-scattering
// has detail, not in a smooth beam.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "render_test_util.h"
#include "app/render_session.h"
#include "renderer/renderer.h"

namespace haze::test {
namespace {

class RefinementTest : public GlTest {};

// Stripes across the gate: detail at the texel scale of a half-resolution buffer near the lens.
std::shared_ptr<GoboImage> stripesGobo() {
  auto g = std::make_shared<GoboImage>();
  g->name = "stripes";
  g->width = g->height = 128;
  g->transmittance.resize(128 * 128);
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x) g->transmittance[static_cast<size_t>(y) * 128 + x] = (x / 8) % 2 == 0 ? 1.0f : 0.0f;
  return g;
}

// A smooth wash beside the striped spot, both seen from the side.
FrameState twoBeams() {
  FrameState frame;
  frame.camera.position = {8.0f, 2.5f, 0.0f};
  frame.camera.target = {0.0f, 2.5f, 0.0f};
  frame.camera.fovYDeg = 50.0f;
  frame.medium.scattering = 0.05f;
  BeamState spot = makeBeam({0.0f, 6.0f, -1.5f}, {0.0f, -1.0f, 0.0f}, 18.0f, 26.0f, 60000.0f);
  spot.optics.gobo = stripesGobo();
  spot.poseKey = 1;
  BeamState wash = makeBeam({0.0f, 6.0f, 2.0f}, {0.0f, -1.0f, 0.0f}, 20.0f, 40.0f, 20000.0f);
  wash.poseKey = 2;
  frame.beams = {spot, wash};
  return frame;
}

ImageRGB renderWith(const Venue& venue, const FrameState& frame, RenderSettings s, uint64_t* refined = nullptr) {
  s.timePasses = refined != nullptr;
  auto r = Renderer::create(venue, s);
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
  if (!r.ok()) return {};
  (*r)->render(frame);
  if (refined) *refined = (*r)->lastTimes().refinedPixels;
  return (*r)->readRadiance();
}

bool close(const glm::vec3& a, const glm::vec3& b) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(a[c] - b[c]) > 1e-5f * std::max({std::abs(a[c]), std::abs(b[c]), 1e-3f})) return false;
  return true;
}

TEST_F(RefinementTest, EachPixelIsTheUpsampledOrTheFullResolutionValue) {
  const Venue venue = floorVenue(16.0f, 0.5f);
  const FrameState frame = twoBeams();
  constexpr int w = 320, h = 240;
  const RenderSettings base{.width = w, .height = h, .planes = 48, .scatterDivisor = 2, .minSamplesPerChord = 16};
  // The default preset's refinement (it refines from 1280 pixels wide; here at 320 for the time).
  const RenderSettings preset = renderSettingsFor(Quality::Default, 1280, 720);
  ASSERT_GT(preset.refineCurvature, 0.0f);
  RenderSettings refinedSettings = base;
  refinedSettings.refineCurvature = preset.refineCurvature;
  refinedSettings.refineFloor = preset.refineFloor;
  RenderSettings full = base;
  full.scatterDivisor = 1;
  uint64_t counted = 0;
  const ImageRGB refined = renderWith(venue, frame, refinedSettings, &counted);
  const ImageRGB upsampled = renderWith(venue, frame, base);
  const ImageRGB fine = renderWith(venue, frame, full);
  ASSERT_EQ(refined.pixels.size(), size_t{w} * h);
  ASSERT_EQ(upsampled.pixels.size(), refined.pixels.size());
  ASSERT_EQ(fine.pixels.size(), refined.pixels.size());

  size_t asFine = 0, asUpsampled = 0, neither = 0, fineLeft = 0, fineRight = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      const bool isFine = close(refined.pixels[i], fine.pixels[i]);
      const bool isUp = close(refined.pixels[i], upsampled.pixels[i]);
      if (isFine && !isUp) {
        ++asFine;
        // The camera looks along -X: the striped spot (z = -1.5) is on the right, the wash left.
        (x < w / 2 ? fineLeft : fineRight) += 1;
      } else if (isUp) {
        ++asUpsampled;
      } else {
        ++neither;
      }
    }
  std::printf("[ refinement ] %llu pixels counted as refined; %zu take the full-resolution value (%zu left, %zu right), "
              "%zu the upsampled one, %zu neither\n",
              static_cast<unsigned long long>(counted), asFine, fineLeft, fineRight, asUpsampled, neither);
  EXPECT_EQ(neither, 0u) << "a refined image holds only upsampled and full-resolution values";
  EXPECT_GT(asFine, 500u) << "the stripes must be refined";
  // Pixels where both agree (no light) may be marked too, so the count bounds what differs.
  EXPECT_GE(counted, asFine);
  // Measured: 1616 pixels counted (2.1 % of the frame), 1168 of the differing ones on the
  // striped spot's side and 348 on the wash's (its bright end at the lens).
  EXPECT_LT(counted, size_t{w} * h * 8 / 100) << "refinement is for detail, not the whole frame";
  EXPECT_GT(fineRight, 2 * fineLeft) << "the striped spot is refined far more than the smooth wash";
}

TEST_F(RefinementTest, NothingIsRefinedAtFullResolutionOrWhenOff) {
  const Venue venue = floorVenue(16.0f, 0.5f);
  const FrameState frame = twoBeams();
  uint64_t counted = 1;
  renderWith(venue, frame, {.width = 160, .height = 120, .scatterDivisor = 1, .refineCurvature = 0.2f}, &counted);
  EXPECT_EQ(counted, 0u);
  counted = 1;
  renderWith(venue, frame, {.width = 160, .height = 120, .scatterDivisor = 2, .refineCurvature = 0.0f}, &counted);
  EXPECT_EQ(counted, 0u);
}

}  // namespace
}  // namespace haze::test
