// The MVR import's overview camera and its ray cast (shows/import/mvr_camera.h) on geometry built
// here, whose answers are known by construction: a closed box room around a rig.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "shows/import/mvr_camera.h"
#include "unit/import/frame_place.h"

namespace haze {
namespace {

// The 12 triangles of the box lo..hi.
std::vector<glm::vec3> box(const glm::vec3& lo, const glm::vec3& hi) {
  std::vector<glm::vec3> t;
  auto quad = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) { t.insert(t.end(), {a, b, c, a, c, d}); };
  const glm::vec3 p[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                          {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
  quad(p[0], p[1], p[2], p[3]);
  quad(p[4], p[5], p[6], p[7]);
  quad(p[0], p[1], p[5], p[4]);
  quad(p[3], p[2], p[6], p[7]);
  quad(p[0], p[3], p[7], p[4]);
  quad(p[1], p[2], p[6], p[5]);
  return t;
}

// The venue as the import builds it for ray casts: bare triangles and the scene's BVH.
struct RayScene {
  explicit RayScene(std::vector<glm::vec3> triangles) : venue(venueFromTriangles(std::move(triangles))), bvh(venue) {}
  Venue venue;
  Bvh bvh;
};

TEST(MvrCamera, FirstHitIsTheNearestWallFromInside) {
  const RayScene room(box({-5, 0, -5}, {5, 4, 5}));
  EXPECT_NEAR(firstHitM(room.bvh, {0, 1, 0}, {0, 0, 1}), 5.0f, 1e-5f);
  EXPECT_NEAR(firstHitM(room.bvh, {0, 1, 0}, {0, 1, 0}), 3.0f, 1e-5f);
  EXPECT_NEAR(firstHitM(room.bvh, {2, 1, 0}, {1, 0, 0}), 3.0f, 1e-5f);
  const glm::vec3 diagonal = glm::normalize(glm::vec3(1, 1, 1));  // reaches the ceiling first
  EXPECT_NEAR(firstHitM(room.bvh, {0, 1, 0}, diagonal), 3.0f * std::sqrt(3.0f), 1e-4f);
  EXPECT_LT(firstHitM(room.bvh, {0, 10, 0}, {0, 1, 0}), 0.0f);        // above the box, looking up
  EXPECT_LT(firstHitM(room.bvh, {0, 1, 0}, {0, 0, 1}, 4.0f), 0.0f);   // the wall is beyond maxM
  EXPECT_LT(firstHitM(RayScene({}).bvh, {0, 1, 0}, {0, 0, 1}), 0.0f);
}

// Many runs of triangles (the boxes that let a ray skip them): the nearest hit is found
// whichever run it is in, the same as testing every triangle.
TEST(MvrCamera, FirstHitOverManyRunsIsTheNearest) {
  std::vector<glm::vec3> tris;
  for (int i = 0; i < 100; ++i) {  // 100 small boxes along +Z at z = 2, 4, ... 200
    const auto b = box({-0.5f, -0.5f, 2.0f * static_cast<float>(i + 1) - 0.1f}, {0.5f, 0.5f, 2.0f * static_cast<float>(i + 1) + 0.1f});
    tris.insert(tris.begin(), b.begin(), b.end());  // the nearest last
  }
  const RayScene scene(tris);
  EXPECT_NEAR(firstHitM(scene.bvh, {0, 0, 0}, {0, 0, 1}), 1.9f, 1e-5f);
  EXPECT_NEAR(firstHitM(scene.bvh, {0, 0, 101}, {0, 0, -1}), 101.0f - 100.1f, 1e-4f);
  EXPECT_LT(firstHitM(scene.bvh, {2, 0, 0}, {0, 0, 1}), 0.0f);  // beside them all
}

TEST(MvrCamera, OpenStageKeepsTheFullDistance) {
  // No venue: back 1.2 and up 0.4 times the rig's diagonal (here 10 m) from its middle.
  const std::vector<glm::vec3> rig = {{-5, 6, 0}, {5, 6, 0}};
  const CameraDef cam = mvrOverviewCamera(rig, RayScene({}).bvh);
  EXPECT_EQ(cam.name, "MVR overview");
  EXPECT_LT(glm::length(cam.target - glm::vec3(0, 6, 0)), 1e-4f);
  EXPECT_LT(glm::length(cam.position - glm::vec3(0, 10, 12)), 0.011f);
  // The rig spans +-5 m across at 12.65 m: tan 0.395, at 16:9 a vertical tan of 0.222 (25
  // degrees with 8 % to spare), below the 30 degrees an open stage keeps at least.
  EXPECT_FLOAT_EQ(cam.fovYDeg, 30.0f);
}

TEST(MvrCamera, RigFillingAClosedRoomIsFramedWhole) {
  // A 30 x 9 x 18 m room whose left half is hung with a grid of pendants at 8 m, their pools on
  // the floor: no view from the audience wall straight on holds it, the camera must turn and
  // widen, and still stand inside the room.
  const glm::vec3 lo(-15, 0, -8), hi(15, 9, 10.5f);
  std::vector<glm::vec3> rig;
  for (float x = -14.0f; x <= 0.0f; x += 2.0f) {
    for (float z = -7.0f; z <= 10.0f; z += 2.5f) {
      rig.push_back({x, 8.0f, z});
      rig.push_back({x, 0.01f, z});
    }
  }
  const RayScene room(box(lo, hi));
  const CameraDef cam = mvrOverviewCamera(rig, room.bvh);
  for (int k = 0; k < 3; ++k) {  // 0.3 m short of the wall along a slanted ray: 0.1 m at least
    EXPECT_GT(cam.position[k], lo[k] + 0.1f) << k;
    EXPECT_LT(cam.position[k], hi[k] - 0.1f) << k;
  }
  EXPECT_GT(cam.position.z, 0.0f);  // the audience half
  EXPECT_LE(cam.fovYDeg, 75.0f);
  for (const glm::vec3& p : rig) {
    const glm::vec2 at = framePlace(cam, p);
    EXPECT_LE(std::abs(at.x), 1.0f) << p.x << " " << p.y << " " << p.z;
    EXPECT_LE(std::abs(at.y), 1.0f) << p.x << " " << p.y << " " << p.z;
  }
}

TEST(MvrCamera, ClosedRoomPutsTheCameraInside) {
  // The rig of a 10 m line at 6 m in a 12 x 8 x 12 m hall: the full distance (12.6 m) would
  // leave the hall; the camera stands inside it (0.3 m short of a wall along its ray), looking
  // at the rig, with a field of view widened for it.
  const glm::vec3 lo(-6, 0, -6), hi(6, 8, 6);
  const std::vector<glm::vec3> rig = {{-5, 6, 0}, {5, 6, 0}};
  const RayScene hall(box(lo, hi));
  const CameraDef cam = mvrOverviewCamera(rig, hall.bvh);
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(cam.position[k], lo[k] + 0.2f) << k;
    EXPECT_LT(cam.position[k], hi[k] - 0.2f) << k;
  }
  EXPECT_GT(cam.position.z, 5.0f);  // from the audience side, set back
  const float d = glm::length(cam.position - cam.target);
  EXPECT_GT(d, 5.0f);
  EXPECT_GT(cam.fovYDeg, 40.0f);
  EXPECT_LE(cam.fovYDeg, 75.0f);
  // Nothing between the camera and the rig's middle.
  const float hit = firstHitM(hall.bvh, cam.target, glm::normalize(cam.position - cam.target));
  EXPECT_GT(hit, d);
}

TEST(MvrCamera, BoxedInRigFallsBackToThePlainView) {
  // The rig's middle inside a 0.4 m crate: no direction has a metre of room; the plain view.
  const std::vector<glm::vec3> rig = {{-5, 6, 0}, {5, 6, 0}};
  const CameraDef cam = mvrOverviewCamera(rig, RayScene(box({-0.2f, 5.8f, -0.2f}, {0.2f, 6.2f, 0.2f})).bvh);
  EXPECT_LT(glm::length(cam.position - glm::vec3(0, 10, 12)), 0.011f);
}

}  // namespace
}  // namespace haze
