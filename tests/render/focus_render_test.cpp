// Focus on a top-down floor render (docs/physics.md, "Focus"): a gobo whose left half is opaque
// puts a straight edge across the pool; defocusing the lens widens the edge, 10 % to 90 %, by
// 2 * 0.687 * b gate radii (a disc of radius b across a step), which the test turns into pixels
// from its own geometry, on the GPU and in the CPU reference; the two agree within the limit
// the other floor tests use. Each image is divided by the same beam without the gobo, so the
// lamp's falloff and the floor's cosine cancel and only the gate's transmittance is left.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/trigonometric.hpp>

#include "app/render_session.h"
#include "fixtures/focus_blur.h"
#include "render_test_util.h"
#include "renderer/reference/reference.h"
#include "renderer/renderer.h"
#include "shows/scene/image_compare.h"

namespace haze::test {
namespace {

constexpr int kSize = 160;
constexpr float kLensHeightM = 4.0f;
constexpr float kFieldDeg = 30.0f;
constexpr float kCameraHeightM = 10.0f;
constexpr float kCameraFovDeg = 20.0f;

FrameState floorFrame(bool gobo, float blur) {
  FrameState f;
  f.camera.position = {0.0f, kCameraHeightM, 0.0f};
  f.camera.target = {0.0f, 0.0f, 0.0f};
  f.camera.up = {0.0f, 0.0f, -1.0f};
  f.camera.fovYDeg = kCameraFovDeg;
  BeamState b = makeBeam({0.0f, kLensHeightM, 0.0f}, {0.0f, -1.0f, 0.0f}, 24.0f, kFieldDeg, 20000.0f);
  b.pose = beamFrame({0.0f, kLensHeightM, 0.0f}, {0.0f, -1.0f, 0.0f}, {1.0f, 0.0f, 0.0f});
  // Open for s >= 0.5 (the +x_b half): 1024 pixels across the gate's diameter, so the sharp edge
  // is 0.002 gate radii wide.
  if (gobo) b.optics.gobo = halfOpaqueGobo(1024, false);
  b.optics.focusBlur = blur;
  f.beams.push_back(b);
  return f;
}

// Geometry: the camera looks straight down, +X to the right of the picture; x_b is +X, so the
// gobo's edge u = 0 is the picture's middle column line, and a pixel is this many gate radii.
float pixelInGate() {
  const float halfM = kCameraHeightM * std::tan(glm::radians(kCameraFovDeg * 0.5f));
  const float gateM = kLensHeightM * std::tan(glm::radians(kFieldDeg * 0.5f));
  return 2.0f * halfM / kSize / gateM;
}

// The mean 10-90 % width in pixels of the edge across rows at v = +-0.3..0.6 gate radii (clear
// of the lens's dark back face at the pool's centre), from image / open-beam image.
double edgeWidthPx(const ImageRGB& gated, const ImageRGB& open) {
  const float px = pixelInGate();
  double sum = 0.0;
  int rows = 0;
  for (int j = 0; j < kSize; ++j) {
    const float v = std::abs((1.0f - (static_cast<float>(j) + 0.5f) / kSize * 2.0f) * kSize * 0.5f * px);
    if (v < 0.3f || v > 0.6f) continue;
    std::vector<double> t(kSize, 0.0);
    for (int i = 0; i < kSize; ++i) t[static_cast<size_t>(i)] = open.at(i, j).g > 0.0f ? gated.at(i, j).g / open.at(i, j).g : 0.0;
    // Rises from 0 (left) to 1 (right) across the middle: the first crossings outward of the centre.
    auto crossing = [&](double level) {
      for (int i = kSize / 2 - 20; i < kSize / 2 + 20; ++i) {
        const double a = t[static_cast<size_t>(i)], b = t[static_cast<size_t>(i) + 1];
        if (a < level && b >= level) return i + (level - a) / (b - a);
      }
      return 1e9;
    };
    sum += crossing(0.9) - crossing(0.1);
    ++rows;
  }
  return rows ? sum / rows : 1e9;
}

class FocusRender : public GlTest {};

TEST_F(FocusRender, DefocusWidensTheGoboEdgeByTheDiscsClosedFormOnGpuAndReference) {
  Venue venue = floorVenue(16.0f, 0.5f);
  auto r = Renderer::create(venue, renderSettingsFor(Quality::High, kSize, kSize));
  ASSERT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
  const FrameState openFrame = floorFrame(false, 0.0f);
  (*r)->render(openFrame);
  const ImageRGB gpuOpen = (*r)->readRadiance();
  const ImageRGB refOpen = renderReference(venue, openFrame, kSize, kSize);
  const double d10 = 0.6870;  // the disc's 10 % point in blur radii: (acos d - d sqrt(1 - d^2)) / pi = 0.1
  double sharpGpu = 0, sharpRef = 0;
  // The profile default (sharp 0.5, blur 0.3) at focus 0.5, 0.75 and 1.
  for (float focus : {0.5f, 0.75f, 1.0f}) {
    const float b = focusBlurRadius(focus, kDefaultFocusSharp, kDefaultFocusBlur);
    const FrameState frame = floorFrame(true, b);
    (*r)->render(frame);
    const ImageRGB gpu = (*r)->readRadiance();
    const ImageRGB ref = renderReference(venue, frame, kSize, kSize);
    const double wGpu = edgeWidthPx(gpu, gpuOpen), wRef = edgeWidthPx(ref, refOpen);
    const double predicted = 2.0 * d10 * b / pixelInGate();
    std::printf("[ focus %.2f ] blur %.3f gate radii: edge 10-90 %% width %.2f px on the GPU, %.2f px in the reference; "
                "the disc predicts %.2f px\n", focus, b, wGpu, wRef, predicted);
    if (b == 0.0f) {
      sharpGpu = wGpu, sharpRef = wRef;
      EXPECT_LT(wGpu, 1.5);
      EXPECT_LT(wRef, 1.5);
    } else {
      // The pixel's own footprint (one pixel, box) and the light map's texels widen a sharp edge
      // by what the sharp render measures; the blurred width is the disc's plus at most that.
      EXPECT_GT(wGpu, predicted * 0.93);
      EXPECT_LT(wGpu, predicted * 1.07 + sharpGpu);
      EXPECT_GT(wRef, predicted * 0.93);
      EXPECT_LT(wRef, predicted * 1.07 + sharpRef);
    }
    const auto c = compareImages(gpu, ref);
    ASSERT_TRUE(c.ok());
    std::printf("[ focus %.2f ] GPU against reference: mean relative error %.4f over %zu values\n", focus, c->meanRelError,
                c->values);
    EXPECT_LT(c->meanRelError, 0.03);
  }
}

}  // namespace
}  // namespace haze::test
