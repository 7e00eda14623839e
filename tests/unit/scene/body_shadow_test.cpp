// Which bodies can shadow a beam (shows/scene/body_shadow.h): other fixtures' bodies in the
// cone widened by the lens radius, never the beam's own; and the casters' key, on which the GPU
// caches the beam's shadow map, moves only when a caster does.
#include <gtest/gtest.h>

#include <glm/trigonometric.hpp>

#include "fixtures/body.h"
#include "fixtures/pose.h"
#include "shows/scene/body_shadow.h"

namespace haze {
namespace {

BodyBox box(glm::vec3 c, float half, int fixture) {
  BodyBox b;
  b.centerM = c;
  b.halfSizeM = glm::vec3(half);
  b.fixtureId = fixture;
  return b;
}

BeamState downBeam(int fixture) {
  BeamState b;
  b.fixtureId = fixture;
  b.pose = beamPose({0.0f, 7.0f, 0.0f}, glm::vec3(0.0f), 0.0f, 0.0f, glm::vec3(0.0f));
  b.optics.lensRadiusM = 0.05f;
  return b;
}

TEST(BodyShadow, SphereAgainstCone) {
  const glm::vec3 apex(0.0f), axis(0.0f, 0.0f, 1.0f);
  const float half = glm::radians(10.0f);
  EXPECT_TRUE(sphereMeetsCone({0.0f, 0.0f, 5.0f}, 0.1f, apex, axis, half));
  EXPECT_FALSE(sphereMeetsCone({0.0f, 0.0f, -5.0f}, 0.1f, apex, axis, half));  // behind the lens
  // 5 m out, tan(10 deg) * 5 = 0.88 m off the axis is the cone's edge.
  EXPECT_TRUE(sphereMeetsCone({1.0f, 0.0f, 5.0f}, 0.2f, apex, axis, half));
  EXPECT_FALSE(sphereMeetsCone({1.2f, 0.0f, 5.0f}, 0.2f, apex, axis, half));
  EXPECT_TRUE(sphereMeetsCone({0.05f, 0.0f, -0.05f}, 0.1f, apex, axis, half));  // holds the apex
}

TEST(BodyShadow, OtherFixturesInTheConeCastTheBeamsOwnDoNot) {
  const BeamState beam = downBeam(1);
  const float cutoff = glm::radians(15.0f);
  const std::vector<BodyBox> boxes = {
      box({0.0f, 7.2f, 0.0f}, 0.2f, 1),   // the beam's own head, round its lens
      box({0.1f, 4.0f, 0.0f}, 0.2f, 2),   // another fixture's, under the lens
      box({3.0f, 4.0f, 0.0f}, 0.2f, 3),   // beside the cone
      box({0.0f, 9.0f, 0.0f}, 0.2f, 4),   // above the lens
      box({0.1f, 3.0f, 0.0f}, 0.2f, 0)};  // a hand-built frame's body, of no fixture of its own
  const ShadowCasters c = shadowCasters(beam, cutoff, bodyBounds(boxes), bodyBounds(std::vector<BodyMesh>{}));
  EXPECT_EQ(c.boxes, (std::vector<int>{1, 4}));
  EXPECT_TRUE(c.meshes.empty());
  EXPECT_EQ(c.spheres.size(), 2u);
  EXPECT_NE(c.key, 0u);
  // A beam whose fixture owns every body in its cone has none.
  EXPECT_TRUE(shadowCasters(beam, cutoff, bodyBounds(std::vector<BodyBox>{boxes[0]}), {}).empty());
}

TEST(BodyShadow, TheKeyMovesOnlyWithACaster) {
  const BeamState beam = downBeam(1);
  const float cutoff = glm::radians(15.0f);
  std::vector<BodyBox> boxes = {box({0.1f, 4.0f, 0.0f}, 0.2f, 2), box({3.0f, 4.0f, 0.0f}, 0.2f, 3)};
  const uint64_t before = shadowCasters(beam, cutoff, bodyBounds(boxes), {}).key;
  boxes[1].centerM.z += 0.5f;  // a head beside the cone pans: this beam's map stands
  EXPECT_EQ(shadowCasters(beam, cutoff, bodyBounds(boxes), {}).key, before);
  boxes[0].axes = glm::mat3(glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f));
  EXPECT_NE(shadowCasters(beam, cutoff, bodyBounds(boxes), {}).key, before);  // the caster turned
  boxes[0].centerM.x = 3.0f;  // and leaves the cone: the map must lose it
  const ShadowCasters gone = shadowCasters(beam, cutoff, bodyBounds(boxes), {});
  EXPECT_TRUE(gone.empty());
  EXPECT_NE(gone.key, before);
}

}  // namespace
}  // namespace haze
