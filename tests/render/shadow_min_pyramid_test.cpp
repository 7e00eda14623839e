// The shadow maps' least-depth pyramid (shows/scene/depth_pyramid.h, surelyLit in
// shaders/beams.glsl) only skips shadow taps that would all have found the point lit: with it
// the image equals, value for value, the image without it, on the bench stage (columns and a
// slatted panel shadowing the deck and the haze), with soft and with hard shadows, surfaces and
// in-scattering both. A pyramid that claimed a texel too far (a lookup a texel short, or
// llvmpipe's one mip level per quad for a fetch whose level differs from pixel to pixel, which
// the first version hit) lights shadowed pixels and fails here.
#include <algorithm>
#include <cmath>

#include "app/bench_scene.h"
#include "render_test_util.h"
#include "renderer/renderer.h"

namespace haze::test {
namespace {

class ShadowMinPyramid : public GlTest {};

ImageRGB render(const Venue& venue, const FrameState& frame, bool pyramid) {
  RenderSettings s{.width = 320, .height = 180, .shadowMapSize = 512, .planes = 24, .scatterDivisor = 2};
  s.shadowMinPyramid = pyramid;
  auto r = Renderer::create(venue, s);
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
  if (!r.ok()) return {};
  (*r)->render(frame);
  return (*r)->readRadiance();
}

void expectSameImage(bool soft) {
  const Venue venue = benchVenue(16);
  FrameState frame = benchFrame(16);
  frame.softShadows = soft;
  const ImageRGB with = render(venue, frame, true);
  const ImageRGB without = render(venue, frame, false);
  ASSERT_EQ(with.pixels.size(), without.pixels.size());
  ASSERT_FALSE(with.pixels.empty());
  size_t differing = 0;
  float maxL = 0.0f, maxDiff = 0.0f;
  for (size_t i = 0; i < with.pixels.size(); ++i) {
    maxL = std::max({maxL, without.pixels[i].r, without.pixels[i].g, without.pixels[i].b});
    const float d = std::max({std::abs(with.pixels[i].r - without.pixels[i].r),
                              std::abs(with.pixels[i].g - without.pixels[i].g),
                              std::abs(with.pixels[i].b - without.pixels[i].b)});
    differing += d > 0.0f;
    maxDiff = std::max(maxDiff, d);
  }
  ASSERT_GT(maxL, 1.0f);  // lit, so a wrongly lit shadow could not hide
  EXPECT_EQ(differing, 0u) << (soft ? "soft" : "hard") << " shadows: largest difference " << maxDiff << " of "
                           << maxL;
}

TEST_F(ShadowMinPyramid, SoftShadowsAreUnchanged) { expectSameImage(true); }
TEST_F(ShadowMinPyramid, HardShadowsAreUnchanged) { expectSameImage(false); }

}  // namespace
}  // namespace haze::test
