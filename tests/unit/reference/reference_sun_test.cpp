// The reference's sun (docs/physics.md, "The sun") against closed forms: the direction
// convention, a floor lit at elevation e (E sin(e) rho / pi), a roof's shadow, the in-scattering
// of a ray wholly in the sun (sigma_s p E exp(-sigma_t H) (1 - exp(-sigma_t L)) / sigma_t) and
// the same ray in a closed room, which the sun cannot reach.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/reference/reference.h"
#include "renderer/reference/sun.h"
#include "shows/scene/physics.h"
#include "unit/scene/test_scenes.h"

namespace haze {
namespace {

using test::kPiD;

void expectVec(glm::vec3 a, glm::vec3 b) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-6f) << c;
}

TEST(ReferenceSun, AzimuthCountsFromNorthTowardsEast) {
  // Light travels away from the sun: a sun in the north (-Z) on the horizon shines towards +Z.
  expectVec(sunDirection(0.0f, 0.0f), {0.0f, 0.0f, 1.0f});
  expectVec(sunDirection(90.0f, 0.0f), {-1.0f, 0.0f, 0.0f});  // east is +X
  expectVec(sunDirection(180.0f, 0.0f), {0.0f, 0.0f, -1.0f});
  expectVec(sunDirection(37.0f, 90.0f), {0.0f, -1.0f, 0.0f});
  const glm::vec3 d = sunDirection(30.0f, 40.0f);
  EXPECT_NEAR(-d.y, std::sin(40.0 * kPiD / 180.0), 1e-6);
}

FrameState sunFrame(float elevationDeg, float lux) {
  FrameState f;
  f.camera.position = {0, 10, 0};
  f.camera.target = {0, 0, 0};
  f.camera.up = {0, 0, -1};
  f.sun.on = true;
  f.sun.direction = sunDirection(120.0f, elevationDeg);
  f.sun.illuminance = glm::vec3(lux, 0.5f * lux, 0.25f * lux);
  return f;
}

TEST(ReferenceSun, AFloorGetsESinElevationRhoOverPi) {
  Venue v = test::emptyVenue();
  test::addFloor(v, 0.0f, 20.0f, test::addMaterial(v, glm::vec3(0.5f)));
  const Bvh bvh(v);
  for (float el : {90.0f, 60.0f, 25.0f, 5.0f}) {
    const FrameState f = sunFrame(el, 20000.0f);
    const glm::vec3 L = radianceAlongRay(bvh, f, f.camera.position, {0, -1, 0}).total();
    const double expected = 20000.0 * std::sin(el * kPiD / 180.0) * 0.5 / kPiD;
    EXPECT_NEAR(L.r, expected, 1e-4 * expected) << el;
    EXPECT_NEAR(L.g, 0.5 * expected, 1e-4 * expected) << el;
  }
  // Below the horizon the sun lights the floor's underside only: seen from above, nothing.
  const FrameState below = sunFrame(-30.0f, 20000.0f);
  EXPECT_EQ(radianceAlongRay(bvh, below, below.camera.position, {0, -1, 0}).total(), glm::vec3(0.0f));
}

TEST(ReferenceSun, ARoofShadowsTheFloorUnderIt) {
  Venue v = test::emptyVenue();
  const int grey = test::addMaterial(v, glm::vec3(0.5f));
  test::addFloor(v, 0.0f, 20.0f, grey);
  test::addQuad(v, {-2, 3, -2}, {2, 3, -2}, {2, 3, 2}, {-2, 3, 2}, grey);  // a 4 m roof, 3 m up
  const Bvh bvh(v);
  const FrameState f = sunFrame(90.0f, 10000.0f);
  // Seen from under the roof: the floor below it is dark, the floor beyond lit.
  const glm::vec3 eye(0, 1, 0);
  EXPECT_EQ(radianceAlongRay(bvh, f, eye, {0, -1, 0}).total(), glm::vec3(0.0f));
  EXPECT_GT(radianceAlongRay(bvh, f, eye, glm::normalize(glm::vec3(4, -1, 0))).total().r, 1000.0f);
}

// An open box 10 m across and H = 4 m tall (floor, four walls, no roof), the eye at 2 m looking
// along +X to the wall L = 5 m away; sun straight down, so s(x) = 2 m all along the ray.
struct OpenRoom {
  Venue venue;
  OpenRoom(bool roof) {
    venue = test::emptyVenue();
    const int grey = test::addMaterial(venue, glm::vec3(0.5f));
    test::addFloor(venue, 0.0f, 5.0f, grey);
    test::addQuad(venue, {5, 0, -5}, {5, 4, -5}, {5, 4, 5}, {5, 0, 5}, grey);
    test::addQuad(venue, {-5, 0, -5}, {-5, 4, -5}, {-5, 4, 5}, {-5, 0, 5}, grey);
    test::addQuad(venue, {-5, 0, 5}, {5, 0, 5}, {5, 4, 5}, {-5, 4, 5}, grey);
    test::addQuad(venue, {-5, 0, -5}, {5, 0, -5}, {5, 4, -5}, {-5, 4, -5}, grey);
    if (roof) test::addQuad(venue, {-5, 4, -5}, {5, 4, -5}, {5, 4, 5}, {-5, 4, 5}, grey);
  }
};

TEST(ReferenceSun, ARayInTheSunMatchesTheIntegral) {
  const OpenRoom room(false);
  const Bvh bvh(room.venue);
  ASSERT_NEAR(room.venue.boundsMax.y, 4.0f, 1e-6f);
  FrameState f = sunFrame(90.0f, 50000.0f);
  f.sun.illuminance = glm::vec3(50000.0f);
  for (float sigmaA : {0.0f, 0.05f}) {
    f.medium.scattering = 0.08f;
    f.medium.absorption = sigmaA;
    const double st = f.medium.extinction(), ss = f.medium.scattering, H = 2.0, L = 5.0;
    // The eye looks across the light: a = 90 degrees, the hazy lobe's p(90) = (1 + 9/8) / (13 pi).
    const double p = (1.0 + 9.0 / 8.0) / (13.0 * kPiD);
    const double expected = ss * p * 50000.0 * std::exp(-st * H) * (1.0 - std::exp(-st * L)) / st;
    const PixelRadiance px = radianceAlongRay(bvh, f, {0, 2, 0}, {1, 0, 0});
    EXPECT_NEAR(px.inScattered.r, expected, 1e-4 * expected) << sigmaA;
    EXPECT_NEAR(sunInScatter(bvh, f.medium, f.sun, {0, 2, 0}, {1, 0, 0}, 5.0f).r, expected, 1e-4 * expected);
  }
}

TEST(ReferenceSun, AClosedRoomKeepsTheSunOut) {
  const OpenRoom room(true);
  const Bvh bvh(room.venue);
  FrameState f = sunFrame(50.0f, 50000.0f);
  f.medium.scattering = 0.08f;
  const PixelRadiance px = radianceAlongRay(bvh, f, {0, 2, 0}, glm::normalize(glm::vec3(1, -0.3f, 0.2f)));
  EXPECT_EQ(px.inScattered, glm::vec3(0.0f));
  EXPECT_EQ(px.surface, glm::vec3(0.0f));
}

TEST(ReferenceSun, AHalfShadedRayCountsTheLitPartOnly) {
  // A roof over x < 0 only: of a ray from x = -4 to the wall at x = 5, the part beyond x = 0 is
  // in the sun (straight down), found by bisection to well under a step.
  OpenRoom room(false);
  test::addQuad(room.venue, {-5, 4, -5}, {0, 4, -5}, {0, 4, 5}, {-5, 4, 5}, 1);
  const Bvh bvh(room.venue);
  FrameState f = sunFrame(90.0f, 1000.0f);
  f.sun.illuminance = glm::vec3(1000.0f);
  f.medium.scattering = 0.1f;
  const double st = 0.1, p = (1.0 + 9.0 / 8.0) / (13.0 * kPiD);
  // t from 4 to 9 lit: integral of exp(-st (2 + t)).
  const double expected = 0.1 * p * 1000.0 * std::exp(-st * 2.0) * (std::exp(-st * 4.0) - std::exp(-st * 9.0)) / st;
  const glm::vec3 L = sunInScatter(bvh, f.medium, f.sun, {-4, 2, 0}, {1, 0, 0}, 9.0f, 0.3f);
  EXPECT_NEAR(L.r, expected, 1e-4 * expected);
}

}  // namespace
}  // namespace haze
