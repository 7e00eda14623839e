// The reference's surface term and camera against answers worked out by hand: a Lambertian floor
// under a beam (0.5 / pi * I / h^2 and its off-axis cosine / r^2 form, pixel by pixel through the
// pinhole), shadows, two-sidedness, ambient, emission and the background's attenuation.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/reference/reference.h"
#include "shows/scene/physics.h"
#include "unit/scene/test_scenes.h"

namespace haze {
namespace {

using test::kPiD;

constexpr float kH = 4.0f;  // lamp height over the floor

FrameState downBeamFrame(std::shared_ptr<const Distribution> dist, float fieldDeg) {
  FrameState f;
  f.camera.position = {0, 10, 0};
  f.camera.target = {0, 0, 0};
  f.camera.up = {0, 0, -1};
  f.camera.fovYDeg = 60.0f;
  f.beams.push_back(test::makeBeam({0, kH, 0}, {0, -1, 0}, std::move(dist), fieldDeg));
  return f;
}

Venue floorVenue(bool faceDown = false) {
  Venue v = test::emptyVenue();
  const int grey = test::addMaterial(v, glm::vec3(0.5f));
  test::addFloor(v, 0.0f, 20.0f, grey, faceDown);
  return v;
}

glm::vec3 pixelAt(const Bvh& bvh, const FrameState& f, glm::vec3 target) {
  const glm::vec3 o = f.camera.position;
  return radianceAlongRay(bvh, f, o, glm::normalize(target - o)).total();
}

TEST(ReferenceSurface, FloorUnderTheBeamIsHalfOverPiTimesIOverHSquared) {
  const Venue v = floorVenue();
  const FrameState f = downBeamFrame(test::parametric(20, 35, 1000), 35);
  // Odd size: the centre pixel's ray goes straight down, under the beam.
  const ImageRGB img = renderReference(v, f, 33, 25);
  ASSERT_EQ(img.width, 33);
  ASSERT_EQ(img.height, 25);
  const double expected = 0.5 / kPiD * 1000.0 / (kH * kH);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(img.at(16, 12)[c], expected, 0.005 * expected);
}

TEST(ReferenceSurface, OffAxisFollowsCosineOverRSquaredPixelByPixel) {
  // Uniform 2000 cd out to 40 degrees: L = 0.5 / pi * I * cos(theta) / r^2 = 0.5/pi I h / r^3.
  const Venue v = floorVenue();
  const FrameState f = downBeamFrame(test::uniformDistribution(40.0f, 2000.0f), 80.0f);
  const int w = 64, h = 48;
  const ImageRGB img = renderReference(v, f, w, h);
  // docs/physics.md's pinhole, written out: camera 10 m up looking down, image top towards -z.
  const double tanHalf = std::tan(30.0 * kPiD / 180.0), aspect = double(w) / h;
  int lit = 0, dark = 0;
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const double x = 10.0 * tanHalf * aspect * (2.0 * (i + 0.5) / w - 1.0);
      const double z = -10.0 * tanHalf * (1.0 - 2.0 * (j + 0.5) / h);
      const double rho = std::sqrt(x * x + z * z);
      const double thetaDeg = std::atan2(rho, double(kH)) * 180.0 / kPiD;
      if (std::fabs(thetaDeg - 40.0) < 0.5) continue;  // the beam's edge
      const double r = std::sqrt(rho * rho + kH * kH);
      const double expected = thetaDeg < 40.0 ? 0.5 / kPiD * 2000.0 * kH / (r * r * r) : 0.0;
      (expected > 0 ? lit : dark)++;
      ASSERT_NEAR(img.at(i, j).g, expected, 0.005 * expected + 1e-9) << i << ", " << j;
    }
  }
  EXPECT_GT(lit, 500);
  EXPECT_GT(dark, 200);
}

TEST(ReferenceSurface, OccluderCastsAnExactShadow) {
  Venue v = floorVenue();
  // A 1 m square halfway up: its shadow on the floor is the 2 m square |x|, |z| < 1.
  test::addFloor(v, kH / 2, 0.5f);
  const Bvh bvh(v);
  FrameState f = downBeamFrame(test::parametric(30, 50, 1000), 50);
  f.camera.position = {5, 1, 0.3f};  // low, so the eye rays pass under the occluder
  EXPECT_EQ(pixelAt(bvh, f, {0, 0, 0}), glm::vec3(0.0f));
  EXPECT_EQ(pixelAt(bvh, f, {0.95f, 0, 0.3f}), glm::vec3(0.0f));
  EXPECT_EQ(pixelAt(bvh, f, {-0.9f, 0, -0.9f}), glm::vec3(0.0f));
  // Just outside the shadow: fully lit, 0.5/pi I(theta) cos(theta) / r^2.
  const Distribution& d = *f.beams[0].optics.distribution;
  for (float x : {1.05f, 1.5f}) {
    const double r = std::sqrt(double(x) * x + kH * kH);
    const double theta = std::atan2(double(x), double(kH));
    const double expected = 0.5 / kPiD * d.intensityCd(float(theta), 0.0f) * (kH / r) / (r * r);
    EXPECT_NEAR(pixelAt(bvh, f, {x, 0, 0}).r, expected, 0.005 * expected) << x;
  }
}

TEST(ReferenceSurface, LensClearanceIgnoresGeometryAtTheLens) {
  // A housing 2 cm under the lens blocks everything, unless it is within the clearance.
  Venue v = floorVenue();
  test::addFloor(v, kH - 0.02f, 0.2f);
  const Bvh bvh(v);
  FrameState f = downBeamFrame(test::parametric(20, 35, 1000), 35);
  f.camera.position = {3, 2, 0};  // below the housing
  const glm::vec3 dir = glm::normalize(glm::vec3(0.3f, 0, 0.2f) - f.camera.position);
  EXPECT_EQ(radianceAlongRay(bvh, f, f.camera.position, dir).total(), glm::vec3(0.0f));
  ReferenceOptions clear;
  clear.lensClearanceM = 0.05f;
  EXPECT_GT(radianceAlongRay(bvh, f, f.camera.position, dir, clear).total().r, 1.0f);
}

TEST(ReferenceSurface, SurfacesAreTwoSided) {
  const FrameState f = downBeamFrame(test::parametric(20, 35, 1000), 35);
  const Venue up = floorVenue(false), down = floorVenue(true);
  const Bvh bvhUp(up), bvhDown(down);
  for (glm::vec3 target : {glm::vec3(0, 0, 0), glm::vec3(0.7f, 0, -0.4f)}) {
    const glm::vec3 a = pixelAt(bvhUp, f, target), b = pixelAt(bvhDown, f, target);
    EXPECT_GT(a.r, 0.0f);
    EXPECT_NEAR(a.r, b.r, 1e-6f * a.r);
  }
  // Seen from below, the floor's underside is lit by nothing: the lamp is behind its plane.
  FrameState below = f;
  below.camera.position = {0.5f, -3, 0.5f};
  EXPECT_EQ(pixelAt(bvhUp, below, {0, 0, 0}), glm::vec3(0.0f));
  EXPECT_EQ(pixelAt(bvhDown, below, {0, 0, 0}), glm::vec3(0.0f));
}

TEST(ReferenceSurface, AmbientAndEmissionAreAddedAndAttenuated) {
  Venue v = test::emptyVenue();
  const int m = test::addMaterial(v, glm::vec3(0.2f, 0.4f, 0.8f), glm::vec3(3.0f, 0.0f, 1.0f));
  test::addQuad(v, {-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, m);  // the wall z = 0
  const Bvh bvh(v);
  FrameState f;
  f.camera.position = {0, 0, 10};
  f.medium.ambient = glm::vec3(2.0f);
  const glm::vec3 l = radianceAlongRay(bvh, f, {0, 0, 10}, {0, 0, -1}).total();
  EXPECT_NEAR(l.r, 0.2f * 2.0f + 3.0f, 1e-5f);
  EXPECT_NEAR(l.g, 0.4f * 2.0f + 0.0f, 1e-5f);
  EXPECT_NEAR(l.b, 0.8f * 2.0f + 1.0f, 1e-5f);
  // Through absorbing haze (sigma_a only: no in-scattering) the wall 10 m away is dimmed.
  f.medium.absorption = 0.1f;
  const PixelRadiance p = radianceAlongRay(bvh, f, {0, 0, 10}, {0, 0, -1});
  EXPECT_TRUE(p.hitSurface);
  EXPECT_NEAR(p.depthM, 10.0f, 1e-5f);
  EXPECT_NEAR(p.total().r, (0.4f + 3.0f) * std::exp(-1.0f), 1e-5f);
  EXPECT_EQ(p.inScattered, glm::vec3(0.0f));
}

TEST(ReferenceSurface, BackgroundIsAttenuatedOverTheFarDistance) {
  const Venue v = test::emptyVenue();
  FrameState f;
  f.camera.farM = 30.0f;
  f.medium.background = {1.0f, 2.0f, 3.0f};
  f.medium.absorption = 0.05f;
  const ImageRGB img = renderReference(v, f, 8, 6);
  const float t = std::exp(-0.05f * 30.0f);
  for (const glm::vec3& p : img.pixels) {
    EXPECT_NEAR(p.r, 1.0f * t, 1e-6f);
    EXPECT_NEAR(p.b, 3.0f * t, 1e-6f);
  }
  // Scattering counts in the extinction too: sigma_t = sigma_s + sigma_a (no beams, no L_in).
  f.medium.scattering = 0.02f;
  const Bvh bvh(v);
  const PixelRadiance p = radianceAlongRay(bvh, f, {0, 0, 0}, {0, 0, -1});
  EXPECT_FALSE(p.hitSurface);
  EXPECT_NEAR(p.depthM, 30.0f, 1e-6f);
  EXPECT_NEAR(p.total().g, 2.0f * std::exp(-0.07f * 30.0f), 1e-6f);
  // A wall beyond far is not seen: the background is.
  Venue wall = test::emptyVenue();
  test::addQuad(wall, {-50, -50, -40}, {50, -50, -40}, {50, 50, -40}, {-50, 50, -40});
  const Bvh wallBvh(wall);
  const PixelRadiance q = radianceAlongRay(wallBvh, f, {0, 0, 0}, {0, 0, -1});
  EXPECT_FALSE(q.hitSurface);
  EXPECT_NEAR(q.total().g, 2.0f * std::exp(-0.07f * 30.0f), 1e-6f);
}

TEST(ReferenceSurface, DarkBeamsAddNothing) {
  const Venue v = floorVenue();
  FrameState f = downBeamFrame(test::parametric(20, 35, 1000), 35);
  f.medium.scattering = 0.1f;
  f.beams[0].optics.dimmer = 0.0f;
  f.beams.push_back(test::makeBeam({0, kH, 0}, {0, -1, 0}, nullptr, 35));  // no photometry
  for (const glm::vec3& p : renderReference(v, f, 12, 9).pixels) EXPECT_EQ(p, glm::vec3(0.0f));
}

}  // namespace
}  // namespace haze
