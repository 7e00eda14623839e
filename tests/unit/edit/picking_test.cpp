// Picking without a window (shows/edit/picking.h): the camera maps points to the pixels the renderer
// draws them at, rays hit the venue's triangles, a fixture placed on a surface hangs under it,
// stands on it or points out of a wall, clicks find fixtures (their bodies, their mounting points)
// and beams, and the selection rule.
#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/gtx/intersect.hpp>

#include "shows/edit/picking.h"
#include "fixtures/body.h"
#include "fixtures/gdtf.h"
#include "fixtures/pose.h"
#include "unit/scene/test_scenes.h"
#include "test_data.h"

namespace haze {
namespace {

using test::addBox;
using test::addFloor;
using test::emptyVenue;

CameraState lookingDownZ() {
  CameraState c;
  c.position = {0.0f, 0.0f, 10.0f};
  c.target = {0.0f, 0.0f, 0.0f};
  c.fovYDeg = 90.0f;
  return c;
}

TEST(Picking, ProjectsLikeAPerspectiveCamera) {
  // 90 degrees vertical on 200 x 100: at 10 m the view spans 20 m high and 40 m wide.
  const ViewCamera view(lookingDownZ(), {200.0f, 100.0f});
  const auto centre = view.project({0.0f, 0.0f, 0.0f});
  ASSERT_TRUE(centre);
  EXPECT_NEAR(centre->x, 100.0f, 1e-3f);
  EXPECT_NEAR(centre->y, 50.0f, 1e-3f);
  const auto rightUp = view.project({10.0f, 5.0f, 0.0f});  // a quarter of the width right, half up
  ASSERT_TRUE(rightUp);
  EXPECT_NEAR(rightUp->x, 150.0f, 1e-3f);
  EXPECT_NEAR(rightUp->y, 25.0f, 1e-3f);
  EXPECT_FALSE(view.project({0.0f, 0.0f, 20.0f}));  // behind the camera
}

TEST(Picking, RayThroughAPixelProjectsBackToIt) {
  CameraState c;
  c.position = {3.0f, 4.2f, 10.5f};
  c.target = {-1.0f, 2.0f, -3.0f};
  c.fovYDeg = 42.0f;
  const ViewCamera view(c, {250.0f, 341.0f});
  for (glm::vec2 px : {glm::vec2(0.0f, 0.0f), glm::vec2(125.0f, 170.5f), glm::vec2(249.0f, 12.0f), glm::vec2(30.0f, 300.0f)}) {
    const Ray r = view.ray(px);
    EXPECT_NEAR(glm::length(r.dir), 1.0f, 1e-5f);
    const auto back = view.project(r.origin + 7.0f * r.dir);
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->x, px.x, 1e-3f);
    EXPECT_NEAR(back->y, px.y, 1e-3f);
  }
}

TEST(Picking, CastsAgainstTheVenueAndTurnsTheNormalToTheViewer) {
  Venue v = emptyVenue();
  addFloor(v, 0.0f, 10.0f, 0, /*faceDown=*/true);  // wound facing down, seen from above
  const Bvh bvh(v);
  const auto hit = castVenue(bvh, Ray{{1.0f, 5.0f, 2.0f}, {0.0f, -1.0f, 0.0f}});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distanceM, 5.0f, 1e-4f);
  EXPECT_NEAR(hit->surface.positionM.x, 1.0f, 1e-4f);
  EXPECT_NEAR(hit->surface.positionM.z, 2.0f, 1e-4f);
  EXPECT_GT(hit->normal.y, 0.99f);  // the side the ray came from
  EXPECT_FALSE(castVenue(bvh, Ray{{1.0f, 5.0f, 2.0f}, {0.0f, 1.0f, 0.0f}}));
}

// A pipe 5 cm square 10 m ahead of a wall 20 m away, seen straight on.
struct PipeScene {
  Venue venue = emptyVenue();
  PipeScene() {
    addBox(venue, {-5.0f, 2.975f, -0.025f}, {5.0f, 3.025f, 0.025f});  // the pipe, at y = 3
    addBox(venue, {-20.0f, -20.0f, -10.2f}, {20.0f, 20.0f, -10.0f});  // the wall
  }
};

TEST(Picking, SnapsToAThinMemberNearThePointer) {
  PipeScene s;
  const Bvh bvh(s.venue);
  CameraState c;
  c.position = {0.0f, 3.0f, 10.0f};
  c.target = {0.0f, 3.0f, 0.0f};
  c.fovYDeg = 40.0f;
  const ViewCamera view(c, {640.0f, 360.0f});
  // The pipe spans about 2.5 px at 10 m; 3 px above its centre the pixel shows the wall.
  const auto pipe = view.project({0.0f, 3.0f, 0.0f});
  ASSERT_TRUE(pipe);
  const glm::vec2 beside = *pipe - glm::vec2(0.0f, 3.0f);
  const auto exact = pickVenue(bvh, view, beside, 0.0f);
  ASSERT_TRUE(exact);
  EXPECT_NEAR(exact->surface.positionM.z, -10.0f, 1e-3f);  // the wall
  const auto snapped = pickVenue(bvh, view, beside, 6.0f);
  ASSERT_TRUE(snapped);
  EXPECT_NEAR(snapped->surface.positionM.z, 0.025f, 1e-3f);  // the pipe's front face
  // Far from anything thin, snapping keeps the wall.
  const auto wall = pickVenue(bvh, view, *pipe + glm::vec2(0.0f, 60.0f), 6.0f);
  ASSERT_TRUE(wall);
  EXPECT_NEAR(wall->surface.positionM.z, -10.0f, 1e-3f);
}

// The resting beam of a mounting rotation, through the pose code the renderer uses.
glm::vec3 restingBeam(const glm::vec3& rotationDeg) {
  return glm::normalize(beamPose(glm::vec3(0.0f), rotationDeg, 0.0f, 0.0f, glm::vec3(0.0f)).zb);
}

TEST(Picking, MountsHangingUnderStandingOnAndOutOfWalls) {
  Venue v = emptyVenue();
  addBox(v, {-3.0f, 7.0f, -3.0f}, {3.0f, 7.5f, 3.0f});    // a ceiling slab 0.5 m thick
  addFloor(v, 0.0f, 10.0f);                                // the floor
  addBox(v, {-5.0f, 0.0f, -6.2f}, {5.0f, 6.0f, -6.0f});    // a wall facing +z
  addBox(v, {-4.0f, 4.96f, 1.95f}, {4.0f, 5.0f, 2.05f});   // a pipe 4 cm tall at y = 5
  const Bvh bvh(v);

  const auto under = castVenue(bvh, Ray{{1.0f, 3.0f, 0.5f}, {0.0f, 1.0f, 0.0f}});
  ASSERT_TRUE(under);
  MountPose m = mountOnSurface(*under);
  EXPECT_EQ(m.kind, MountPose::Kind::Hanging);
  EXPECT_NEAR(m.positionM.y, 7.0f, 1e-4f);
  EXPECT_NEAR(glm::dot(restingBeam(m.rotationDeg), glm::vec3(0, -1, 0)), 1.0f, 1e-5f);

  const auto floor = castVenue(bvh, Ray{{4.0f, 3.0f, 4.0f}, {0.0f, -1.0f, 0.0f}});
  ASSERT_TRUE(floor);
  m = mountOnSurface(*floor);
  EXPECT_EQ(m.kind, MountPose::Kind::Standing);
  EXPECT_NEAR(m.positionM.y, 0.0f, 1e-4f);
  EXPECT_NEAR(glm::dot(restingBeam(m.rotationDeg), glm::vec3(0, 1, 0)), 1.0f, 1e-5f);

  const auto wall = castVenue(bvh, Ray{{2.0f, 3.0f, 0.0f}, glm::normalize(glm::vec3(0.3f, 0.0f, -1.0f))});
  ASSERT_TRUE(wall);
  m = mountOnSurface(*wall);
  EXPECT_EQ(m.kind, MountPose::Kind::Wall);
  EXPECT_NEAR(m.positionM.z, -6.0f, 1e-4f);
  EXPECT_NEAR(glm::dot(restingBeam(m.rotationDeg), glm::vec3(0, 0, 1)), 1.0f, 1e-5f);

  // The side of the pipe, seen from the front: it hangs from the pipe's underside.
  const auto pipe = castVenue(bvh, Ray{{0.5f, 4.98f, 8.0f}, {0.0f, 0.0f, -1.0f}});
  ASSERT_TRUE(pipe);
  EXPECT_NEAR(pipe->surface.positionM.z, 2.05f, 1e-4f);
  m = mountOnSurface(*pipe);
  EXPECT_EQ(m.kind, MountPose::Kind::Hanging);
  EXPECT_NEAR(m.positionM.y, 4.96f, 1e-4f);
  EXPECT_NEAR(m.positionM.x, 0.5f, 1e-4f);
}

TEST(Picking, RotationForAnyBeamDirection) {
  for (glm::vec3 d : {glm::vec3(0, -1, 0), glm::vec3(0, 1, 0), glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0),
                      glm::vec3(0, 0, -1), glm::vec3(0.3f, -0.5f, 0.8f), glm::vec3(-0.7f, 0.6f, -0.2f)}) {
    const glm::vec3 want = glm::normalize(d);
    EXPECT_NEAR(glm::dot(restingBeam(rotationForBeamDirection(d)), want), 1.0f, 1e-5f)
        << d.x << " " << d.y << " " << d.z;
  }
}

TEST(Picking, DragPlanes) {
  const Ray r{{0.0f, 10.0f, 0.0f}, glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f))};
  const auto p = intersectHorizontalPlane(r, 8.0f);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->x, 2.0f, 1e-4f);
  EXPECT_NEAR(p->y, 8.0f, 1e-4f);
  EXPECT_FALSE(intersectHorizontalPlane(r, 12.0f));  // behind the ray
  EXPECT_FALSE(intersectHorizontalPlane(Ray{{0, 1, 0}, {1, 0, 0}}, 0.0f));
  // A horizontal ray at height 3 passes the vertical line through (5, 0, 0) at height 3.
  const glm::vec3 q = closestOnVerticalLine(Ray{{0.0f, 3.0f, 4.0f}, {0.0f, 0.0f, -1.0f}}, {0.0f, 0.0f, 0.0f});
  EXPECT_NEAR(q.y, 3.0f, 1e-4f);
  EXPECT_NEAR(q.x, 0.0f, 1e-6f);
}

struct RigScene {
  Show show;
  ProfileSet profiles;
  StageState stage;
  RigScene() {
    auto p = std::make_shared<Profile>();
    profiles["spot"] = p;
    for (int i = 0; i < 3; ++i) {
      FixtureDef f;
      f.id = 10 + i;
      f.profile = "spot";
      f.position = {-2.0f + 2.0f * static_cast<float>(i), 6.0f, 0.0f};
      show.fixtures.push_back(f);
      stage[f.id] = Attributes{};
    }
  }
};

TEST(Picking, ClickFindsTheFixtureOrItsBeam) {
  RigScene s;
  const ViewCamera view(lookingDownZ(), {400.0f, 300.0f});
  const glm::vec2 middle = *view.project({0.0f, 6.0f, 0.0f});
  EXPECT_EQ(pickFixture(s.show, s.profiles, s.stage, view, middle + glm::vec2(3.0f, -2.0f)), 11);
  const glm::vec2 left = *view.project({-2.0f, 6.0f, 0.0f});
  EXPECT_EQ(pickFixture(s.show, s.profiles, s.stage, view, left), 10);
  // Half-way down the right fixture's beam (straight down, unlit): nothing, then lit: it.
  const glm::vec2 beam = *view.project({2.0f, 3.0f, 0.0f});
  EXPECT_FALSE(pickFixture(s.show, s.profiles, s.stage, view, beam));
  s.stage[12].intensity = 1.0f;
  EXPECT_EQ(pickFixture(s.show, s.profiles, s.stage, view, beam), 12);
  EXPECT_FALSE(pickFixture(s.show, s.profiles, s.stage, view, beam + glm::vec2(12.0f, 0.0f)));
  // A beam 15 m long by default, shorter where it meets the venue.
  Venue v = emptyVenue();
  addFloor(v, 4.0f, 20.0f);
  const Bvh bvh(v);
  EXPECT_FALSE(pickFixture(s.show, s.profiles, s.stage, view, beam, &bvh));  // below the floor at y = 4
}

// A moving head hung at (0, 6, 0) with the default body of a moving head (head, yoke, base), its
// lens 0.3 m below the pivot; the camera 3 m to its +X side, level with the pivot.
struct MovingHeadScene {
  Show show;
  ProfileSet profiles;
  StageState stage;
  Body body;
  glm::vec3 pivot{0.0f, 6.0f, 0.0f};
  MovingHeadScene() {
    auto p = std::make_shared<Profile>();
    p->lensOffset = {0.0f, -0.3f, 0.0f};
    body = defaultBody(0.05f, {p->lensOffset}, /*moving=*/true);
    p->body = body;
    profiles["head"] = p;
    FixtureDef f;
    f.id = 7;
    f.profile = "head";
    f.position = pivot;
    show.fixtures.push_back(f);
    stage[f.id] = Attributes{};  // dark: no beam to pick
  }
  static CameraState camera() {
    CameraState c;
    c.position = {3.0f, 6.0f, 0.0f};
    c.target = {0.0f, 6.0f, 0.0f};
    c.fovYDeg = 40.0f;
    return c;
  }
  // A point on the head's face towards the camera (its local +X face), 80 % of the way from its
  // centre to its front (lens) end, posed at `tiltDeg`.
  glm::vec3 headPoint(float tiltDeg) const {
    const glm::vec3 local = body.head.centerM + glm::vec3(0.5f * body.head.sizeM.x, -0.4f * body.head.sizeM.y, 0.0f);
    return pivot + headRotation(glm::vec3(0.0f), 0.0f, tiltDeg) * local;
  }
};

TEST(Picking, ClickOnAHeadFarFromItsMountingPointPicksIt) {
  MovingHeadScene s;
  const ViewCamera view(MovingHeadScene::camera(), {800.0f, 600.0f});
  const PickOptions options;
  const glm::vec2 mount = *view.project(s.pivot);
  const glm::vec2 head = *view.project(s.headPoint(0.0f));
  // Beyond the mounting point's radius, and the beam is dark: the old rules found nothing here.
  ASSERT_GT(glm::length(head - mount), options.bodyRadiusPx + 5.0f);
  EXPECT_EQ(pickFixture(s.show, s.profiles, s.stage, view, head), 7);
  EXPECT_EQ(pickFixtureBody(s.show, s.profiles, s.stage, view.ray(head), 100.0f), 7);
  // Beside the head (20 cm towards the camera's right, -Z, clear of the whole body): nothing.
  const glm::vec2 beside = *view.project(s.headPoint(0.0f) + glm::vec3(0.0f, 0.0f, -0.2f));
  EXPECT_FALSE(pickFixture(s.show, s.profiles, s.stage, view, beside));
  // The mounting point still picks (the fallback), as before.
  EXPECT_EQ(pickFixture(s.show, s.profiles, s.stage, view, mount + glm::vec2(4.0f, 0.0f)), 7);
}

TEST(Picking, ClickFollowsTheHeadWhenItTilts) {
  MovingHeadScene s;
  const ViewCamera view(MovingHeadScene::camera(), {800.0f, 600.0f});
  const PickOptions options;
  const glm::vec2 mount = *view.project(s.pivot);
  const glm::vec2 was = *view.project(s.headPoint(0.0f));
  const glm::vec2 now = *view.project(s.headPoint(90.0f));
  ASSERT_GT(glm::length(was - mount), options.bodyRadiusPx + 5.0f);
  ASSERT_GT(glm::length(now - mount), options.bodyRadiusPx + 5.0f);
  ASSERT_GT(glm::length(now - was), 20.0f) << "the head moved on screen";
  EXPECT_EQ(pickFixture(s.show, s.profiles, s.stage, view, was), 7);
  EXPECT_FALSE(pickFixture(s.show, s.profiles, s.stage, view, now));
  s.stage[7].tiltDeg = 90.0f;
  EXPECT_FALSE(pickFixture(s.show, s.profiles, s.stage, view, was)) << "where the head was";
  EXPECT_EQ(pickFixture(s.show, s.profiles, s.stage, view, now), 7) << "where the head is";
}

TEST(Picking, BodyBehindAWallIsNotPicked) {
  MovingHeadScene s;
  const ViewCamera view(MovingHeadScene::camera(), {800.0f, 600.0f});
  const glm::vec2 head = *view.project(s.headPoint(0.0f));
  // A wall between the camera (x = 3) and the fixture: the head is hidden.
  Venue front = emptyVenue();
  addBox(front, {1.5f, 0.0f, -5.0f}, {1.6f, 10.0f, 5.0f});
  const Bvh frontBvh(front);
  EXPECT_FALSE(pickFixture(s.show, s.profiles, s.stage, view, head, &frontBvh));
  // A wall behind it (x = -2): the head is in front of the venue and wins.
  Venue back = emptyVenue();
  addBox(back, {-2.1f, 0.0f, -5.0f}, {-2.0f, 10.0f, 5.0f});
  const Bvh backBvh(back);
  EXPECT_EQ(pickFixture(s.show, s.profiles, s.stage, view, head, &backBvh), 7);
}

// Whether the ray meets any triangle of the posed meshes (glm's own two-sided ray-triangle
// test, the oracle here: independent of the BVH picking goes through).
bool meetsAnyTriangle(const std::vector<BodyMesh>& meshes, const Ray& ray) {
  for (const BodyMesh& m : meshes) {
    const TriangleMesh& t = *m.mesh;
    for (size_t k = 0; k + 2 < t.indices.size(); k += 3) {
      glm::vec2 bary;
      float dist = 0.0f;
      if (glm::intersectRayTriangle(ray.origin, ray.dir, m.originM + m.axes * t.positions[t.indices[k]],
                                    m.originM + m.axes * t.positions[t.indices[k + 1]],
                                    m.originM + m.axes * t.positions[t.indices[k + 2]], bary, dist) &&
          dist > 0.0f)
        return true;
    }
  }
  return false;
}

TEST(Picking, GdtfBodyIsPickedOnItsMeshNotInItsGaps) {
  const char* bmfl = "gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf";
  HAZE_NEED_DATA(bmfl);
  auto g = loadGdtf(test::dataFile(bmfl));
  ASSERT_TRUE(g.ok()) << g.error().str();
  const Body body = g->profile->housing();
  ASSERT_TRUE(body.head.mesh && body.yokeLeft.mesh && body.base.mesh);
  Show show;
  ProfileSet profiles;
  StageState stage;
  profiles["bmfl"] = g->profile;
  FixtureDef f;
  f.id = 3;
  f.profile = "bmfl";
  f.position = {0.0f, 6.0f, 0.0f};
  show.fixtures.push_back(f);
  stage[f.id] = Attributes{};
  CameraState c;
  c.position = {0.4f, 6.1f, 2.5f};
  c.target = {0.0f, 6.0f, 0.0f};
  c.fovYDeg = 40.0f;
  const ViewCamera view(c, {800.0f, 600.0f});
  const PickOptions options;
  const glm::vec2 mount = *view.project(f.position);

  // The triangle of the head's model nearest its lens end: a click on its centroid is on the mesh.
  const TriangleMesh& head = *body.head.mesh;
  size_t lowest = 0;
  float lowestY = std::numeric_limits<float>::infinity();
  for (size_t k = 0; k + 2 < head.indices.size(); k += 3) {
    const float y = head.positions[head.indices[k]].y + head.positions[head.indices[k + 1]].y +
                    head.positions[head.indices[k + 2]].y;
    if (y < lowestY) {
      lowestY = y;
      lowest = k;
    }
  }
  const glm::vec3 centroid = (head.positions[head.indices[lowest]] + head.positions[head.indices[lowest + 1]] +
                              head.positions[head.indices[lowest + 2]]) / 3.0f;
  // Posed at rotation 0, pan 0, tilt 0: the part's frame is the world's, about the pivot.
  const glm::vec2 onMesh = *view.project(f.position + centroid);
  ASSERT_GT(glm::length(onMesh - mount), options.bodyRadiusPx + 5.0f);
  EXPECT_EQ(pickFixture(show, profiles, stage, view, onMesh), 3);

  // A pixel inside a part's bounding box whose ray meets none of the triangles (between the
  // yoke's arms, around the head): nothing is picked there.
  std::vector<BodyBox> boxes;
  std::vector<BodyMesh> meshes;
  poseBody(body, f.position, glm::vec3(0.0f), 0.0f, 0.0f, boxes, &meshes);
  ASSERT_EQ(meshes.size(), 3u);
  poseBody(body, f.position, glm::vec3(0.0f), 0.0f, 0.0f, boxes);  // the parts as their bounding boxes
  ASSERT_EQ(boxes.size(), 3u);
  std::optional<glm::vec2> gap;
  for (int y = 0; y < 600 && !gap; y += 6) {
    for (int x = 0; x < 800 && !gap; x += 6) {
      const glm::vec2 px(static_cast<float>(x), static_cast<float>(y));
      if (glm::length(px - mount) <= options.bodyRadiusPx + 5.0f) continue;
      const Ray r = view.ray(px);
      bool inBox = false;
      for (const BodyBox& b : boxes) inBox = inBox || intersectBox(b, r.origin, r.dir, 100.0f).hit;
      if (inBox && !meetsAnyTriangle(meshes, r)) gap = px;
    }
  }
  ASSERT_TRUE(gap) << "no ray through a bounding box that misses the BMFL's meshes";
  EXPECT_FALSE(pickFixture(show, profiles, stage, view, *gap)) << "pixel " << gap->x << ", " << gap->y;
}

TEST(Picking, SelectionRule) {
  std::vector<int> sel;
  applyClickToSelection(sel, 5, false, false);
  EXPECT_EQ(sel, (std::vector<int>{5}));
  applyClickToSelection(sel, 3, false, true);  // Shift adds
  EXPECT_EQ(sel, (std::vector<int>{3, 5}));
  applyClickToSelection(sel, 3, false, true);  // and never removes
  EXPECT_EQ(sel, (std::vector<int>{3, 5}));
  applyClickToSelection(sel, 9, true, false);  // Ctrl toggles
  EXPECT_EQ(sel, (std::vector<int>{3, 5, 9}));
  applyClickToSelection(sel, 5, true, false);
  EXPECT_EQ(sel, (std::vector<int>{3, 9}));
  applyClickToSelection(sel, std::nullopt, true, false);  // Ctrl+click on nothing keeps it
  EXPECT_EQ(sel, (std::vector<int>{3, 9}));
  applyClickToSelection(sel, 7, false, false);  // a plain click replaces
  EXPECT_EQ(sel, (std::vector<int>{7}));
  applyClickToSelection(sel, std::nullopt, false, false);  // a plain click on nothing clears
  EXPECT_TRUE(sel.empty());
}

}  // namespace
}  // namespace haze
