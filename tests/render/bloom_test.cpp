// Bloom is a display effect: it spreads some light around bright areas of the picture (the
// dark floor just outside a spot's pool gets brighter, the pool itself a little darker) and
// never touches the radiometric image.
#include "render_test_util.h"
#include "renderer/renderer.h"

namespace haze::test {
namespace {

class BloomTest : public GlTest {};

TEST_F(BloomTest, SpreadsLightOnTheDisplayOnly) {
  Venue venue = floorVenue(20.0f, 0.5f);
  FrameState frame;
  frame.camera.position = glm::vec3(0.0f, 8.0f, 0.01f);
  frame.camera.target = glm::vec3(0.0f);  // straight down onto the pool
  frame.camera.fovYDeg = 40.0f;
  frame.beams.push_back(makeBeam({0.0f, 6.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 8.0f, 10.0f, 400000.0f));
  // The lamp hangs between the camera and the pool; its (black) back would hide the pool's centre.
  frame.beams.back().optics.lensRadiusM = 0.0f;
  auto r = Renderer::create(venue, {.width = 128, .height = 128});
  ASSERT_TRUE(r.ok()) << r.error().str();
  (*r)->render(frame);
  const ImageRGB before = (*r)->readRadiance();
  const std::vector<unsigned char> plain = (*r)->readDisplay({.exposureEv = -2.0f});
  const std::vector<unsigned char> glare = (*r)->readDisplay({.exposureEv = -2.0f, .bloom = 0.2f});
  const ImageRGB after = (*r)->readRadiance();
  ASSERT_EQ(before.pixels, after.pixels) << "bloom changed the radiometric image";

  auto grey = [](const std::vector<unsigned char>& rgb, int x, int y) { return rgb[(y * 128 + x) * 3 + 1]; };
  // The pool is about 1 m across under a 10 degree beam from 6 m: 16 pixels of the 5.8 m view.
  ASSERT_GT(grey(plain, 64, 64), 200) << "the pool is bright";
  ASSERT_EQ(grey(plain, 64, 100), 0) << "the floor beside it is dark without bloom";
  EXPECT_GT(grey(glare, 64, 100), 5) << "bloom lights the dark floor near the pool";
  EXPECT_GT(grey(glare, 64, 90), grey(glare, 64, 120)) << "and fades with distance";
  EXPECT_LE(grey(glare, 64, 64), grey(plain, 64, 64)) << "the light is moved, not added";
}

}  // namespace
}  // namespace haze::test
