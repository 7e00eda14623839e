// The venue's spatial chunks (GpuVenue::drawInside): a beam's shadow map and the depth pre-pass
// draw only the chunks their frustum reaches, which must leave every depth as it was: the image
// with the culling equals, value for value, the image that draws every chunk, on the bench
// stage (walls, columns and a slatted panel in chunks inside and outside each narrow beam's
// frustum) with shadows in the haze and on the deck.
#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "app/bench_scene.h"
#include "render_test_util.h"
#include "renderer/gpu_venue.h"
#include "renderer/renderer.h"

namespace haze::test {
namespace {

class VenueChunks : public GlTest {};

ImageRGB render(const Venue& venue, const FrameState& frame, bool cull) {
  RenderSettings s{.width = 320, .height = 180, .shadowMapSize = 512, .planes = 24, .scatterDivisor = 2};
  s.cullVenueChunks = cull;
  auto r = Renderer::create(venue, s);
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
  if (!r.ok()) return {};
  (*r)->render(frame);
  return (*r)->readRadiance();
}

TEST_F(VenueChunks, CullingChangesNoPixel) {
  const Venue venue = benchVenue(16);
  const FrameState frame = benchFrame(16);
  const ImageRGB culled = render(venue, frame, true);
  const ImageRGB all = render(venue, frame, false);
  ASSERT_EQ(culled.pixels.size(), all.pixels.size());
  ASSERT_FALSE(all.pixels.empty());
  size_t differing = 0;
  float maxL = 0.0f;
  for (size_t i = 0; i < all.pixels.size(); ++i) {
    maxL = std::max({maxL, all.pixels[i].r, all.pixels[i].g, all.pixels[i].b});
    differing += culled.pixels[i] != all.pixels[i];
  }
  ASSERT_GT(maxL, 1.0f);
  EXPECT_EQ(differing, 0u);
}

// The culling does cull: a narrow frustum looking at one corner of the stage keeps part of it,
// one looking away from it nothing, and with culling off everything is kept.
TEST_F(VenueChunks, ANarrowFrustumDrawsPartOfTheVenue) {
  const Venue venue = benchVenue(16);
  const GpuVenue culled(venue, true), all(venue, false);
  ASSERT_GT(culled.triangleCount(), 0u);
  const glm::vec3 c = 0.5f * (venue.boundsMin + venue.boundsMax);
  const glm::vec3 eye = c + glm::vec3(0.0f, 2.0f, 0.0f);
  const glm::mat4 proj = glm::perspective(glm::radians(10.0f), 1.0f, 0.02f, 100.0f);
  const glm::mat4 down = proj * glm::lookAt(eye, venue.boundsMin, glm::vec3(0.0f, 1.0f, 0.0f));
  const glm::mat4 away = proj * glm::lookAt(venue.boundsMax + glm::vec3(1.0f), venue.boundsMax + glm::vec3(2.0f),
                                            glm::vec3(0.0f, 1.0f, 0.0f));
  const size_t part = culled.trianglesInside(down);
  EXPECT_GT(part, 0u);
  EXPECT_LT(part, culled.triangleCount());
  EXPECT_EQ(culled.trianglesInside(away), 0u);
  EXPECT_EQ(all.trianglesInside(away), all.triangleCount());
}

}  // namespace
}  // namespace haze::test
