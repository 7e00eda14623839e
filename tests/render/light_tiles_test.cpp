// Tiled light culling (renderer/light_tiles.h) must only skip beams that add nothing: the
// surfaces rendered with the tile masks equal, value for value, the surfaces rendered with every
// pixel trying every beam, on the bench stage (walls, columns, a hanging panel, silhouettes at
// many depths) with one mask word (16 beams) and with several (70 beams).
#include <algorithm>

#include "app/bench_scene.h"
#include "render_test_util.h"
#include "renderer/renderer.h"

namespace haze::test {
namespace {

class LightTilesTest : public GlTest {};

ImageRGB renderSurfaces(const Venue& venue, const FrameState& frame, bool tiled) {
  RenderSettings s{.width = 320, .height = 180};
  s.tiledSurfaces = tiled;
  auto r = Renderer::create(venue, s);
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
  if (!r.ok()) return {};
  (*r)->render(frame);
  return (*r)->readRadiance();
}

void expectSameSurfaces(int fixtures) {
  const Venue venue = benchVenue(fixtures);
  FrameState frame = benchFrame(fixtures);
  frame.medium.scattering = 0.0f;  // surfaces only: the planes pass is not what is tested
  const ImageRGB all = renderSurfaces(venue, frame, false);
  const ImageRGB tiled = renderSurfaces(venue, frame, true);
  ASSERT_EQ(all.pixels.size(), tiled.pixels.size());
  ASSERT_FALSE(all.pixels.empty());
  float maxL = 0.0f, maxDiff = 0.0f;
  for (size_t i = 0; i < all.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      maxL = std::max(maxL, all.pixels[i][c]);
      maxDiff = std::max(maxDiff, std::abs(all.pixels[i][c] - tiled.pixels[i][c]));
    }
  // Lit surfaces, many times brighter than the ambient, so a lost beam could not hide.
  ASSERT_GT(maxL, 1.0f);
  EXPECT_LE(maxDiff, 1e-5f * maxL) << fixtures << " fixtures";
}

TEST_F(LightTilesTest, OneMaskWordLosesNoLight) { expectSameSurfaces(16); }
TEST_F(LightTilesTest, SeveralMaskWordsLoseNoLight) { expectSameSurfaces(70); }

}  // namespace
}  // namespace haze::test
