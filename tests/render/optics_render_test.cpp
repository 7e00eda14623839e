// Beam optics beyond the gobo on the GPU, against the CPU reference: framing blades cut the
// floor pool where the reference cuts it (every pixel more than one pixel from a blade's edge in
// the reference image is lit or dark on the GPU too), and a 3-facet prism's three pools in haze
// agree with the reference image within the tolerance of beams_vs_reference_test.cpp. Two gobo
// wheels: the GPU's pool agrees with the reference and differs from the one-gobo pool. (What the
// frame builder makes of these optics is unit/frame/optics_frame_test.cpp.)
#include <cmath>
#include <cstdio>
#include <utility>

#include <glm/geometric.hpp>

#include "app/render_session.h"
#include "fixtures/blades.h"
#include "fixtures/cells.h"
#include "fixtures/prism.h"
#include "render_test_util.h"
#include "renderer/reference/reference.h"
#include "renderer/renderer.h"
#include "shows/scene/image_compare.h"

namespace haze::test {
namespace {

constexpr int kSize = 160;

FrameState topDown() {
  FrameState f;
  f.camera.position = {0.0f, 10.0f, 0.0f};
  f.camera.target = {0.0f, 0.0f, 0.0f};
  f.camera.up = {0.0f, 0.0f, -1.0f};
  f.camera.fovYDeg = 40.0f;
  return f;
}

BeamState downlight(float beamDeg, float fieldDeg, float peak) {
  BeamState b = makeBeam({0.0f, 4.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, beamDeg, fieldDeg, peak);
  b.pose = beamFrame({0.0f, 4.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, {1.0f, 0.0f, 0.0f});
  return b;
}

class OpticsRender : public GlTest {};

TEST_F(OpticsRender, BladesCutWhereTheReferenceCutsWithinAPixel) {
  Venue venue = floorVenue(16.0f, 0.5f);
  FrameState frame = topDown();
  BeamState b = downlight(24.0f, 30.0f, 20000.0f);
  BladeInsertions in{};
  in[0] = {0.25f, 0.25f};
  in[1] = {0.1f, 0.4f};
  in[3] = {0.3f, 0.0f};
  b.optics.blades = bladeMask(in, 15.0f);
  frame.beams.push_back(b);
  auto r = Renderer::create(venue, renderSettingsFor(Quality::High, kSize, kSize));
  ASSERT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
  (*r)->render(frame);
  const ImageRGB gpu = (*r)->readRadiance();
  const ImageRGB ref = renderReference(venue, frame, kSize, kSize);
  float peak = 0.0f;
  for (const glm::vec3& v : ref.pixels) peak = std::max(peak, v.g);
  ASSERT_GT(peak, 0.0f);
  // Lit: above 2 % of the peak (the pool's tail reaches further out than that). A pixel is
  // checked where its 3x3 neighbourhood in the reference is all lit or all dark.
  auto lit = [&](const ImageRGB& img, int i, int j) { return img.at(i, j).g > 0.02f * peak; };
  int checked = 0, litCount = 0, wrong = 0;
  for (int j = 1; j + 1 < kSize; ++j)
    for (int i = 1; i + 1 < kSize; ++i) {
      int n = 0;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) n += lit(ref, i + di, j + dj);
      if (n != 0 && n != 9) continue;
      ++checked;
      litCount += n == 9;
      if (lit(gpu, i, j) != (n == 9)) ++wrong;
    }
  std::printf("[ blades ] %d pixels checked (%d lit), %d differ from the reference\n", checked, litCount, wrong);
  EXPECT_GT(litCount, 500);  // measured 723 of 160 x 160 (three blades in)
  EXPECT_EQ(wrong, 0);
  const auto c = compareImages(gpu, ref);
  ASSERT_TRUE(c.ok());
  std::printf("[ blades ] mean relative error %.4f over %zu values\n", c->meanRelError, c->values);
  EXPECT_LT(c->meanRelError, 0.03);
}

TEST_F(OpticsRender, PrismPoolsInHazeAgreeWithTheReference) {
  Venue venue = floorVenue(16.0f, 0.5f);
  FrameState frame = topDown();
  frame.camera.position = {0.0f, 3.0f, 10.0f};
  frame.camera.target = {0.0f, 2.0f, 0.0f};
  frame.camera.up = {0.0f, 1.0f, 0.0f};
  frame.camera.fovYDeg = 45.0f;
  frame.medium.scattering = 0.05f;
  BeamState b = downlight(8.0f, 12.0f, 100000.0f);
  b.pose.lensPosition = {0.0f, 6.0f, 0.0f};
  for (const BeamPose& pose : prismCopies(b.pose, PrismSpec{"3", 3, 12.0f, false}, 20.0f)) {
    BeamState copy = b;
    copy.pose = pose;
    copy.optics.dimmer = 1.0f / 3.0f;
    frame.beams.push_back(copy);
  }
  auto r = Renderer::create(venue, renderSettingsFor(Quality::High, 320, 240));
  ASSERT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
  (*r)->render(frame);
  const ImageRGB gpu = (*r)->readRadiance();
  const ImageRGB ref = renderReference(venue, frame, 320, 240);
  const auto c = compareImages(gpu, ref);
  ASSERT_TRUE(c.ok());
  double gpuSum = 0, refSum = 0;
  for (size_t k = 0; k < gpu.pixels.size(); ++k) {
    gpuSum += gpu.pixels[k].g;
    refSum += ref.pixels[k].g;
  }
  std::printf("[ prism ] mean relative error %.4f (max %.4f, leak %.4f) over %zu values; sums %.4g / %.4g\n", c->meanRelError,
              c->maxRelError, c->leak, c->values, gpuSum, refSum);
  EXPECT_LT(c->meanRelError, 0.03);
  if (c->meanRelError >= 0.03)
    for (const auto& file : writeDiagnostics("prism_high", gpu, ref)) std::printf("[ prism ] wrote %s\n", file.c_str());
}

// An 8 x 8 gobo whose left half passes `left` and right half `right`.
std::shared_ptr<GoboImage> halves(float left, float right) {
  auto g = std::make_shared<GoboImage>();
  g->width = g->height = 8;
  g->transmittance.resize(64);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) g->transmittance[static_cast<size_t>(j * 8 + i)] = i < 4 ? left : right;
  return g;
}

TEST_F(OpticsRender, TwoGobosOnTheGpuAgreeWithTheReference) {
  Venue venue = floorVenue(16.0f, 0.5f);
  auto r = Renderer::create(venue, renderSettingsFor(Quality::High, kSize, kSize));
  ASSERT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
  auto draw = [&](bool second) {
    FrameState frame = topDown();
    BeamState b = downlight(24.0f, 30.0f, 20000.0f);
    b.optics.gobo = halves(1.0f, 0.5f);
    if (second) {
      b.optics.gobo2 = halves(0.8f, 0.1f);
      b.optics.gobo2RotationDeg = 90.0f;
    }
    frame.beams.push_back(b);
    (*r)->render(frame);
    return std::pair{(*r)->readRadiance(), renderReference(venue, frame, kSize, kSize)};
  };
  const auto [one, oneRef] = draw(false);
  const auto [two, twoRef] = draw(true);
  const auto c = compareImages(two, twoRef);
  ASSERT_TRUE(c.ok());
  double sumOne = 0, sumTwo = 0;
  for (size_t k = 0; k < one.pixels.size(); ++k) {
    sumOne += one.pixels[k].g;
    sumTwo += two.pixels[k].g;
  }
  std::printf("[ two gobos ] mean relative error %.4f over %zu values; GPU pool with gobo 2 / without %.4f\n",
              c->meanRelError, c->values, sumTwo / sumOne);
  EXPECT_LT(c->meanRelError, 0.03);
  // By hand: gobo 2 passes 0.8 over half the pool and 0.1 over the other half, on top of gobo 1.
  EXPECT_LT(sumTwo / sumOne, 0.6);
  EXPECT_GT(sumTwo / sumOne, 0.3);
  if (c->meanRelError >= 0.03)
    for (const auto& file : writeDiagnostics("two_gobos", two, twoRef)) std::printf("[ two gobos ] wrote %s\n", file.c_str());
}

}  // namespace
}  // namespace haze::test
