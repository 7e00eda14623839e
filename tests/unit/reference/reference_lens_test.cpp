// The reference's lens disc (docs/physics.md, "The lens") against the closed form: from the
// front L_lens = I_eff(w_e) / (pi r^2 cos theta_e) exp(-sigma_t t), from behind black, opaque
// either way (it hides the floor behind it), nothing just outside its radius, and no shadow.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "renderer/reference/reference.h"
#include "shows/scene/physics.h"
#include "unit/scene/test_scenes.h"

namespace haze {
namespace {

using test::kPiD;
constexpr float kR = 0.05f;
const glm::vec3 kLens{0.0f, 3.0f, 0.0f};

Venue greyFloor() {
  Venue v = test::emptyVenue();
  const int grey = test::addMaterial(v, glm::vec3(0.5f));
  test::addFloor(v, 0.0f, 20.0f, grey);
  return v;
}

BeamState lensBeam(glm::vec3 zb, float peakCd) {
  BeamState b = test::makeBeam(kLens, glm::normalize(zb), test::parametric(30, 60, peakCd), 60);
  b.optics.lensRadiusM = kR;
  return b;
}

// The ray from eye through the point of the disc at (a, c) r_lens along (x_b, y_b).
glm::vec3 rayThroughDisc(const BeamState& b, glm::vec3 eye, float a, float c) {
  return glm::normalize(kLens + kR * (a * b.pose.xb + c * b.pose.yb) - eye);
}

TEST(ReferenceLens, FrontFaceIsIntensityOverProjectedArea) {
  const Venue venue = greyFloor();
  const Bvh bvh(venue);
  FrameState f;
  f.medium.absorption = 0.02f;  // extinction without in-scattering
  // The eye 8 m away, 25 degrees off the beam's axis.
  const double off = 25.0 * kPiD / 180.0;
  const glm::vec3 eye = kLens + 8.0f * glm::vec3(float(std::sin(off)), 0.0f, float(std::cos(off)));
  f.beams.push_back(lensBeam({0, 0, 1}, 40000.0f));
  const BeamState& b = f.beams[0];
  const glm::vec3 we = glm::normalize(eye - kLens);
  const double cosE = glm::dot(we, b.pose.zb);
  const double iE = beamIntensityTowards(b, eye).r;
  ASSERT_GT(iE, 1000.0);  // the eye is inside the beam
  const double lLens = iE / (kPiD * kR * kR * cosE);
  const std::array<std::pair<float, float>, 4> points{{{0.0f, 0.0f}, {0.5f, 0.3f}, {-0.9f, 0.0f}, {0.0f, -0.95f}}};
  for (auto [a, c] : points) {
    const glm::vec3 v = rayThroughDisc(b, eye, a, c);
    const PixelRadiance px = radianceAlongRay(bvh, f, eye, v);
    ASSERT_TRUE(px.hitLens) << a << ", " << c;
    const double t = glm::length(kLens + kR * (a * b.pose.xb + c * b.pose.yb) - eye);
    EXPECT_NEAR(px.depthM, t, 1e-4);
    const double expected = lLens * std::exp(-0.02 * t);
    EXPECT_NEAR(px.total().r, expected, 1e-4 * expected) << a << ", " << c;
  }
  // Just outside the rim the ray goes on (to nothing here).
  const PixelRadiance past = radianceAlongRay(bvh, f, eye, rayThroughDisc(b, eye, 1.05f, 0.0f));
  EXPECT_FALSE(past.hitLens);
  EXPECT_EQ(past.total(), glm::vec3(0.0f));
}

TEST(ReferenceLens, BackFaceIsBlackAndHidesTheFloor) {
  const Venue venue = greyFloor();
  const Bvh bvh(venue);
  FrameState f;
  f.medium.ambient = glm::vec3(10.0f);  // the floor shows 5 cd/m^2 of ambient wherever it is seen
  f.beams.push_back(lensBeam({0, -1, 0}, 40000.0f));  // a downlight seen from above
  f.beams.push_back(lensBeam({0, -1, 0}, 40000.0f));
  f.beams[1].pose = beamAlong({1.0f, 3.0f, 0.0f}, {0, -1, 0});
  f.beams[1].optics.dimmer = 0.0f;  // a dark lamp is still an opaque disc
  const glm::vec3 eye{0.3f, 8.0f, 0.2f};
  for (const BeamState& b : f.beams) {
    const PixelRadiance px = radianceAlongRay(bvh, f, eye, glm::normalize(b.pose.lensPosition + glm::vec3(0.01f, 0, 0) - eye));
    EXPECT_TRUE(px.hitLens);
    EXPECT_EQ(px.total(), glm::vec3(0.0f));
  }
  // Beside the lens the floor is seen, and lit by the beam: lenses cast no shadow.
  const PixelRadiance beside = radianceAlongRay(bvh, f, eye, glm::normalize(glm::vec3(0.0f, 0.0f, 0.0f) - eye));
  EXPECT_FALSE(beside.hitLens);
  EXPECT_TRUE(beside.hitSurface);
  const double lit = 0.5 / kPiD * beamIntensityTowards(f.beams[0], {0, 0, 0}).r / 9.0 + 5.0;
  EXPECT_NEAR(beside.total().r, lit, 0.01 * lit);
}

TEST(ReferenceLens, InScatteringInFrontOfTheLensAdds) {
  const Venue venue = greyFloor();
  const Bvh bvh(venue);
  FrameState f;
  f.medium.scattering = 0.05f;
  const glm::vec3 eye = kLens + glm::vec3(0.0f, 0.0f, 8.0f);
  f.beams.push_back(lensBeam({0, 0, 1}, 40000.0f));
  const PixelRadiance px = radianceAlongRay(bvh, f, eye, rayThroughDisc(f.beams[0], eye, 0.4f, 0.2f));
  ASSERT_TRUE(px.hitLens);
  EXPECT_GT(px.inScattered.r, 0.0f);
  EXPECT_TRUE(std::isfinite(px.inScattered.r));
  const double lLens = 40000.0 / (kPiD * kR * kR) * std::exp(-0.05 * px.depthM);
  EXPECT_NEAR(px.surface.r, lLens, 2e-3 * lLens);  // on the axis, cos theta_e ~ 1
}

}  // namespace
}  // namespace haze
