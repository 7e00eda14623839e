// A resized viewport keeps the renderer's programs (compiling them is most of what making a
// renderer costs on llvmpipe), and renders what a renderer made at the new size renders.
#include <gtest/gtest.h>

#include "render_test_util.h"
#include "shows/scene/image_compare.h"
#include "renderer/gl/program.h"
#include "renderer/renderer.h"

namespace haze::test {
namespace {

class RendererResizeTest : public GlTest {};

FrameState hazyFrame() {
  FrameState frame;
  frame.camera.position = glm::vec3(0.0f, 3.0f, 8.0f);
  frame.camera.target = glm::vec3(0.0f);
  frame.camera.fovYDeg = 40.0f;
  frame.medium.scattering = 0.05f;
  frame.beams.push_back(makeBeam({0.0f, 6.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 15.0f, 25.0f, 20000.0f));
  return frame;
}

TEST_F(RendererResizeTest, ResizingTwiceBuildsNoProgram) {
  const Venue venue = floorVenue(20.0f, 0.5f);
  const FrameState frame = hazyFrame();
  const RenderSettings settings{.width = 48, .height = 32, .planes = 16, .scatterDivisor = 2};
  auto r = Renderer::create(venue, settings);
  ASSERT_TRUE(r.ok()) << r.error().str();
  (*r)->render(frame);
  const uint64_t built = gl::programBuildCount();
  ASSERT_TRUE((*r)->resize(80, 56).ok());
  (*r)->render(frame);
  ASSERT_TRUE((*r)->resize(40, 72).ok());
  (*r)->render(frame);
  EXPECT_EQ(gl::programBuildCount(), built) << "a resize must not compile programs";
  EXPECT_EQ((*r)->settings().width, 40);
  EXPECT_EQ((*r)->settings().height, 72);
  EXPECT_EQ((*r)->readDisplay({}).size(), size_t{40} * 72 * 3);

  RenderSettings fresh = settings;
  fresh.width = 40;
  fresh.height = 72;
  auto f = Renderer::create(venue, fresh);
  ASSERT_TRUE(f.ok()) << f.error().str();
  (*f)->render(frame);
  const ImageRGB resized = (*r)->readRadiance(), made = (*f)->readRadiance();
  ASSERT_EQ(resized.width, made.width);
  ASSERT_EQ(resized.height, made.height);
  const auto c = compareImages(resized, made);
  ASSERT_TRUE(c.ok()) << c.error().str();
  EXPECT_GT(c->values, 100u);
  EXPECT_LT(c->maxRelError, 1e-5) << "the resized renderer draws what a new one draws";
}

TEST_F(RendererResizeTest, RejectsSizesCreateRejects) {
  auto r = Renderer::create(floorVenue(4.0f, 0.5f), {.width = 16, .height = 16});
  ASSERT_TRUE(r.ok()) << r.error().str();
  EXPECT_FALSE((*r)->resize(0, 16).ok());
  EXPECT_FALSE((*r)->resize(16, 20000).ok());
  EXPECT_EQ((*r)->settings().width, 16);
}

}  // namespace
}  // namespace haze::test
