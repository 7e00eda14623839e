// Surfaces against docs/physics.md by hand: a Lambertian floor under one fixture, and the pan/tilt
// convention moving the lit spot where the rotation matrices say.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "fixtures/photometry.h"
#include "fixtures/pose.h"
#include "render_test_util.h"
#include "app/render_session.h"
#include "renderer/reference/reference.h"
#include "renderer/renderer.h"
#include "test_data.h"

namespace haze::test {
namespace {

class SurfaceTest : public GlTest {};

constexpr float kPi = 3.14159265358979f;

// Floor albedo 0.5, a fixture straight down from h metres, no haze, no ambient:
// the pixel under the beam is L = 0.5 / pi * I(0) / h^2.
TEST_F(SurfaceTest, FloorUnderBeamMatchesLambertWithinTwoPercent) {
  const float h = 6.0f, peakCd = 20000.0f;
  Venue venue = floorVenue(20.0f, 0.5f);
  FrameState frame;
  frame.camera.position = glm::vec3(0.0f, 3.0f, 8.0f);
  frame.camera.target = glm::vec3(0.0f);  // the image centre looks at the spot's centre
  frame.camera.fovYDeg = 30.0f;
  frame.beams.push_back(makeBeam({0.0f, h, 0.0f}, {0.0f, -1.0f, 0.0f}, 20.0f, 30.0f, peakCd));
  const float i0 = frame.beams[0].optics.intensityCd(0.0f, 0.0f).r;
  ASSERT_NEAR(i0, peakCd, peakCd * 1e-3f) << "the parametric beam's peak is on its axis";

  auto r = Renderer::create(venue, {.width = 64, .height = 64});
  ASSERT_TRUE(r.ok()) << r.error().str();
  (*r)->render(frame);
  const ImageRGB img = (*r)->readRadiance();
  // The exact centre falls between pixels 31 and 32: average the four around it.
  glm::vec3 centre = (img.at(31, 31) + img.at(32, 31) + img.at(31, 32) + img.at(32, 32)) * 0.25f;
  const float expected = 0.5f / kPi * peakCd / (h * h);
  EXPECT_NEAR(centre.r, expected, 0.02f * expected);
  EXPECT_NEAR(centre.g, expected, 0.02f * expected);
  EXPECT_NEAR(centre.b, expected, 0.02f * expected);
  // Far outside the beam the floor is black (no ambient).
  EXPECT_LT(img.at(0, 63).r, 1e-6f);
}

// Haze attenuates both legs: the same floor seen through sigma_t gets exp(-sigma_t (r + T)).
TEST_F(SurfaceTest, ExtinctionAttenuatesLightAndView) {
  const float h = 6.0f, peakCd = 20000.0f, sigmaA = 0.05f;
  Venue venue = floorVenue(20.0f, 0.5f);
  FrameState frame;
  frame.camera.position = glm::vec3(0.0f, 3.0f, 8.0f);
  frame.camera.target = glm::vec3(0.0f);
  frame.camera.fovYDeg = 30.0f;
  frame.medium.absorption = sigmaA;  // absorbing only: no in-scattering to add
  frame.beams.push_back(makeBeam({0.0f, h, 0.0f}, {0.0f, -1.0f, 0.0f}, 20.0f, 30.0f, peakCd));
  auto r = Renderer::create(venue, {.width = 64, .height = 64});
  ASSERT_TRUE(r.ok()) << r.error().str();
  (*r)->render(frame);
  const ImageRGB img = (*r)->readRadiance();
  const glm::vec3 centre = (img.at(31, 31) + img.at(32, 31) + img.at(31, 32) + img.at(32, 32)) * 0.25f;
  const float T = glm::length(frame.camera.position);
  const float expected = 0.5f / kPi * peakCd / (h * h) * std::exp(-sigmaA * (h + T));
  EXPECT_NEAR(centre.r, expected, 0.02f * expected);
}

// The brightness-weighted centre of the lit floor, in world x/z, seen from straight above.
glm::vec2 spotCentre(const ImageRGB& img, const FrameState& frame) {
  double sx = 0, sz = 0, sw = 0;
  const float halfExtent = frame.camera.position.y * std::tan(glm::radians(frame.camera.fovYDeg) * 0.5f);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const float w = img.at(x, y).r;
      // Camera above looking down with up = -Z: image right = +X, image down = +Z.
      const float wx = ((x + 0.5f) / img.width * 2.0f - 1.0f) * halfExtent;
      const float wz = ((y + 0.5f) / img.height * 2.0f - 1.0f) * halfExtent;
      sx += w * wx;
      sz += w * wz;
      sw += w;
    }
  return sw > 0 ? glm::vec2(sx / sw, sz / sw) : glm::vec2(1e9f);
}

// docs/physics.md: M = R * Ry(pan) * Rx(tilt), beam along M * (0, -1, 0). Worked by hand with
// R = identity: Rx(t) * (0, -1, 0) = (0, -cos t, -sin t); then Ry(p) turns it to
// (-sin t sin p, -cos t, -sin t cos p). From height h the spot's centre is at
// h * tan t * (-sin p, -cos p) in (x, z).
TEST_F(SurfaceTest, PanTiltMovesTheSpotWherePhysicsSays) {
  const float h = 5.0f;
  Venue venue = floorVenue(30.0f, 0.5f);
  auto r = Renderer::create(venue, {.width = 128, .height = 128});
  ASSERT_TRUE(r.ok()) << r.error().str();
  struct Case { float panDeg, tiltDeg; };
  for (const Case c : {Case{0, 0}, Case{0, 30}, Case{90, 30}, Case{-45, 20}, Case{180, 25}}) {
    FrameState frame;
    frame.camera.position = glm::vec3(0.0f, 12.0f, 0.0f);
    frame.camera.target = glm::vec3(0.0f);
    frame.camera.up = glm::vec3(0.0f, 0.0f, -1.0f);
    frame.camera.fovYDeg = 60.0f;
    BeamState b = makeBeam({0, h, 0}, {0, -1, 0}, 6.0f, 10.0f, 10000.0f);
    b.pose = beamPose({0, h, 0}, {0, 0, 0}, c.panDeg, c.tiltDeg, {0, 0, 0});
    b.poseKey = static_cast<uint64_t>(c.panDeg * 1000 + c.tiltDeg + 5000);
    frame.beams.push_back(b);
    (*r)->render(frame);
    const glm::vec2 got = spotCentre((*r)->readRadiance(), frame);
    const float t = glm::radians(c.tiltDeg), p = glm::radians(c.panDeg);
    const glm::vec2 want = h * std::tan(t) * glm::vec2(-std::sin(p), -std::cos(p));
    // The centroid of a tilted spot sits slightly past its axis point (the far side spreads
    // more); 8 cm at these tilts.
    EXPECT_NEAR(got.x, want.x, 0.08f) << "pan " << c.panDeg << " tilt " << c.tiltDeg;
    EXPECT_NEAR(got.y, want.y, 0.08f) << "pan " << c.panDeg << " tilt " << c.tiltDeg;
  }
}

// A white box under the 10-degree EULUMDAT flood, whose light reaches 80 degrees: its shadow
// frustum is 162 degrees wide, a texel ten times a spot's, and the lit faces came out mottled
// (a diagonal lattice: the PCF taps compared a face against its own depth a texel away). Over
// the pixels where the reference is smooth (every neighbour within 5 %: no silhouette or
// shadow edge, whose staircase at this shadow-map resolution is another matter), the GPU
// must be as smooth. Measured at default: 2.1 % before the slant-scaled offset, 1.3 % after
// (the rest is the light map: the flood's core spans few texels of a map that reaches 80 degrees).
TEST_F(SurfaceTest, LitFacesUnderAWideFloodAreNotMottled) {
  HAZE_NEED_DATA("photometry/ldt/eulumdat-rs/4058075580664_FL_MAX_LUM_1200W_757_SYM_10_WAL.ldt");
  Venue venue = floorVenue(16.0f, 0.3f);
  venue.materials.push_back(Material{.name = "white", .baseColor = glm::vec4(0.9f, 0.9f, 0.9f, 1.0f)});
  addBox(venue, {-0.6f, 0.0f, -0.6f}, {0.6f, 1.2f, 0.6f});
  FrameState frame;
  frame.camera.position = {3.0f, 3.0f, 4.0f};
  frame.camera.target = {0.0f, 0.6f, 0.0f};
  frame.camera.fovYDeg = 40.0f;
  const glm::vec3 lens(-2.0f, 6.0f, 3.0f);
  frame.beams.push_back(fileBeam("ldt/eulumdat-rs/4058075580664_FL_MAX_LUM_1200W_757_SYM_10_WAL.ldt", lens,
                                 glm::vec3(0.0f, 0.6f, 0.0f) - lens));
  constexpr int w = 240, h = 180;
  auto r = Renderer::create(venue, renderSettingsFor(Quality::Default, w, h));
  ASSERT_TRUE(r.ok()) << r.error().str();
  (*r)->render(frame);
  const ImageRGB gpu = (*r)->readRadiance();
  const ImageRGB ref = renderReference(venue, frame, w, h);
  float peak = 0.0f;
  for (const glm::vec3& p : ref.pixels) peak = std::max(peak, p.g);
  double sum = 0.0;
  int n = 0;
  for (int y = 1; y < h - 1; ++y)
    for (int x = 1; x < w - 1; ++x) {
      const float c = ref.at(x, y).g;
      if (!(c > 0.05f * peak)) continue;
      bool smooth = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) smooth = smooth && std::abs(ref.at(x + dx, y + dy).g - c) < 0.05f * c;
      if (!smooth) continue;
      sum += std::abs(gpu.at(x, y).g - c) / c;
      ++n;
    }
  ASSERT_GE(n, 1000) << "too few smooth lit pixels compared";
  const double error = sum / n;
  std::printf("[ box_under_flood_default ] mean relative error %.4f over %d smooth lit pixels\n", error, n);
  EXPECT_LT(error, 0.017);  // fails the mottled faces of before
}

}  // namespace
}  // namespace haze::test
