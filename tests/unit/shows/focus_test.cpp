// Focus to point: the beam axis (from fixtures/pose.h, the renderer's own pose) passes through the
// point for random mountings, positions and lens offsets; the nearest of the equivalent pan/tilt
// answers wins; out-of-reach points get the nearest reachable direction.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "fixtures/pose.h"
#include "shows/focus.h"

namespace haze {
namespace {

// Distance from p to the beam axis ahead of the lens (to the lens when p is behind it).
float axisMiss(const FocusRequest& r, float panDeg, float tiltDeg, glm::vec3 p) {
  BeamPose b = beamPose(r.positionM, r.rotationDeg, panDeg, tiltDeg, r.lensOffsetM);
  glm::vec3 d = p - b.lensPosition;
  float along = glm::dot(d, b.zb);
  return along > 0.0f ? glm::length(d - along * b.zb) : glm::length(d);
}

TEST(Focus, BeamPassesThroughReachablePointsForRandomFixtures) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> angle(-180.0f, 180.0f), pos(-10.0f, 10.0f), offset(-0.3f, 0.3f),
      distance(1.0f, 25.0f), pan(-270.0f, 270.0f), tilt(-135.0f, 135.0f);
  int tried = 0;
  for (int i = 0; i < 2000; ++i) {
    FocusRequest r;
    r.positionM = {pos(rng), pos(rng) + 10.0f, pos(rng)};
    r.rotationDeg = {angle(rng), angle(rng), angle(rng)};
    r.lensOffsetM = {offset(rng), offset(rng), offset(rng)};
    r.currentPanDeg = pan(rng);
    r.currentTiltDeg = tilt(rng);
    // A point the fixture can reach by construction: along its beam at some pan/tilt in range.
    BeamPose aimed = beamPose(r.positionM, r.rotationDeg, pan(rng), tilt(rng), r.lensOffsetM);
    glm::vec3 point = aimed.lensPosition + distance(rng) * aimed.zb;
    FocusResult f = focusOnPoint(r, point);
    ++tried;
    ASSERT_TRUE(f.reached) << "case " << i << ": " << f.note;
    EXPECT_TRUE(r.panDeg.contains(f.panDeg) && r.tiltDeg.contains(f.tiltDeg)) << f.panDeg << " " << f.tiltDeg;
    EXPECT_LT(axisMiss(r, f.panDeg, f.tiltDeg, point), 0.01f) << "case " << i;
    EXPECT_LT(f.missM, 0.001f);
  }
  EXPECT_EQ(tried, 2000);
}

TEST(Focus, WithFullTiltAndNoLensOffsetEveryPointIsReached) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> angle(-180.0f, 180.0f), pos(-20.0f, 20.0f);
  for (int i = 0; i < 1000; ++i) {
    FocusRequest r;
    r.positionM = {pos(rng), pos(rng), pos(rng)};
    r.rotationDeg = {angle(rng), angle(rng), angle(rng)};
    r.tiltDeg = {-180.0f, 180.0f};
    glm::vec3 point{pos(rng), pos(rng), pos(rng)};
    if (glm::length(point - r.positionM) < 0.5f) continue;
    FocusResult f = focusOnPoint(r, point);
    ASSERT_TRUE(f.reached) << i;
    EXPECT_LT(axisMiss(r, f.panDeg, f.tiltDeg, point), 0.01f) << i;
  }
}

TEST(Focus, PicksTheEquivalentAnswerNearestTheCurrentPanTilt) {
  // Hanging straight down at the origin: pan 90, tilt 45 aims along (-sin45, -cos45, 0)
  // (docs/physics.md: beam = (-sin t sin p, -cos t, -sin t cos p)). The same beam comes from
  // (-270, 45), (-90, -45) and (270, -45).
  FocusRequest r;
  glm::vec3 point{-2.0f, -2.0f, 0.0f};
  struct Case {
    float currentPan, currentTilt, pan, tilt;
  } cases[] = {{80, 40, 90, 45}, {-100, -30, -90, -45}, {260, -50, 270, -45}, {-260, 50, -270, 45}};
  for (const Case& c : cases) {
    r.currentPanDeg = c.currentPan;
    r.currentTiltDeg = c.currentTilt;
    FocusResult f = focusOnPoint(r, point);
    ASSERT_TRUE(f.reached);
    EXPECT_NEAR(f.panDeg, c.pan, 1e-3) << c.currentPan;
    EXPECT_NEAR(f.tiltDeg, c.tilt, 1e-3) << c.currentPan;
  }
  // A pan range of -90..90 leaves only (90, 45) and (-90, -45).
  r.panDeg = {-90.0f, 90.0f};
  r.currentPanDeg = 260;
  r.currentTiltDeg = -50;
  FocusResult f = focusOnPoint(r, point);
  EXPECT_NEAR(f.panDeg, 90.0f, 1e-3);
  EXPECT_NEAR(f.tiltDeg, 45.0f, 1e-3);
}

TEST(Focus, LensOffsetTurnsWithTheHead) {
  // A hanging fixture whose lens sits 0.2 m below and 0.1 m along +Z of the pivot (head frame).
  // Pointing at a spot 5 m straight below the lens' rest position needs no pan or tilt at all.
  FocusRequest r;
  r.positionM = {1.0f, 8.0f, -2.0f};
  r.lensOffsetM = {0.0f, -0.2f, 0.1f};
  FocusResult f = focusOnPoint(r, {1.0f, 2.8f, -1.9f});
  ASSERT_TRUE(f.reached);
  EXPECT_NEAR(f.panDeg, 0.0f, 1e-3);
  EXPECT_NEAR(f.tiltDeg, 0.0f, 1e-3);
  // Ignoring the offset would aim from the pivot: 0.1 m over 5.2 m, 1.1 degrees off.
  r.currentTiltDeg = 10.0f;
  glm::vec3 side{4.0f, 0.0f, 3.0f};
  f = focusOnPoint(r, side);
  ASSERT_TRUE(f.reached);
  EXPECT_LT(axisMiss(r, f.panDeg, f.tiltDeg, side), 1e-3f);
}

TEST(Focus, OutOfTiltRangeGivesTheNearestReachableDirection) {
  // Tilt limited to +/-90: a point above the fixture cannot be reached; the nearest direction is
  // horizontal, towards the point's side (+X), 71.57 degrees (atan(3/1)) below it.
  FocusRequest r;
  r.positionM = {0.0f, 5.0f, 0.0f};
  r.tiltDeg = {-90.0f, 90.0f};
  FocusResult f = focusOnPoint(r, {1.0f, 8.0f, 0.0f});
  EXPECT_FALSE(f.reached);
  EXPECT_NE(f.note.find("outside the fixture's ranges"), std::string::npos) << f.note;
  EXPECT_NEAR(std::abs(f.tiltDeg), 90.0f, 1e-3);
  BeamPose b = beamPose(r.positionM, r.rotationDeg, f.panDeg, f.tiltDeg, r.lensOffsetM);
  EXPECT_NEAR(b.zb.x, 1.0f, 1e-4);
  EXPECT_NEAR(b.zb.y, 0.0f, 1e-4);
  EXPECT_NEAR(f.missAngleDeg, std::atan2(3.0f, 1.0f) * 180.0f / 3.14159265f, 0.01);
  EXPECT_TRUE(r.panDeg.contains(f.panDeg));

  // Straight above, every pan is as good: the head keeps its current pan.
  r.currentPanDeg = 33.0f;
  r.currentTiltDeg = 80.0f;
  f = focusOnPoint(r, {0.0f, 9.0f, 0.0f});
  EXPECT_FALSE(f.reached);
  EXPECT_NEAR(f.panDeg, 33.0f, 1e-3);
  EXPECT_NEAR(f.tiltDeg, 90.0f, 1e-3);
  EXPECT_NEAR(f.missAngleDeg, 90.0f, 1e-2);
}

TEST(Focus, OutOfPanRangeClampsPan) {
  // Pan 0..90 only, tilt 0..90: beam = (-sin t sin p, -cos t, -sin t cos p). A point along +X
  // and down needs pan -90 (or 270): the nearest reachable aim keeps pan 0 or 90 and the error
  // is what the search says, never better than a grid-free brute force over the ranges.
  FocusRequest r;
  r.panDeg = {0.0f, 90.0f};
  r.tiltDeg = {0.0f, 90.0f};
  glm::vec3 point{3.0f, -3.0f, 0.0f};
  FocusResult f = focusOnPoint(r, point);
  EXPECT_FALSE(f.reached);
  EXPECT_TRUE(r.panDeg.contains(f.panDeg) && r.tiltDeg.contains(f.tiltDeg));
  float bestDeg = 1e9f;
  for (float p = 0; p <= 90.0f; p += 0.25f)
    for (float t = 0; t <= 90.0f; t += 0.25f) {
      BeamPose b = beamPose(r.positionM, r.rotationDeg, p, t, r.lensOffsetM);
      float c = glm::dot(b.zb, glm::normalize(point - b.lensPosition));
      bestDeg = std::min(bestDeg, std::acos(std::clamp(c, -1.0f, 1.0f)) * 180.0f / 3.14159265f);
    }
  EXPECT_LE(f.missAngleDeg, bestDeg + 0.01f);
  // Straight down (tilt 0) is 45 degrees off; nothing in the ranges does better.
  EXPECT_NEAR(f.missAngleDeg, 45.0f, 0.01f);
}

TEST(Focus, PointsTheLensOffsetCannotReachAreReportedNotCrashed) {
  // The lens 0.1 m to the side of the pan axis: the beam axis always passes 0.1 m from the pan
  // axis, so a point on the pan axis is out of reach whatever the ranges.
  FocusRequest r;
  r.lensOffsetM = {0.1f, 0.0f, 0.0f};
  r.tiltDeg = {-180.0f, 180.0f};
  FocusResult f = focusOnPoint(r, {0.0f, -5.0f, 0.0f});
  EXPECT_FALSE(f.reached);
  EXPECT_NE(f.note.find("lens offset"), std::string::npos) << f.note;
  EXPECT_TRUE(std::isfinite(f.panDeg) && std::isfinite(f.tiltDeg));
  EXPECT_LT(f.missAngleDeg, 2.0f);  // atan(0.1/5) = 1.15 degrees is the best there is
  f = focusOnPoint(r, r.positionM);
  EXPECT_FALSE(f.reached);
  EXPECT_TRUE(std::isfinite(f.panDeg) && std::isfinite(f.tiltDeg));
}

TEST(Focus, UsesTheFixtureAndProfile) {
  FixtureDef fixture;
  fixture.position = {0.0f, 6.0f, 0.0f};
  fixture.rotationDeg = {0.0f, 0.0f, 180.0f};  // standing on the floor, beam up at rest
  Profile profile;
  profile.lensOffset = {0.0f, -0.15f, 0.0f};
  profile.tiltDeg = {-120.0f, 120.0f};
  glm::vec3 point{2.0f, 10.0f, 1.0f};
  FocusResult f = focusOnPoint(fixture, profile, point, 0.0f, 0.0f);
  ASSERT_TRUE(f.reached) << f.note;
  FocusRequest r;
  r.positionM = fixture.position;
  r.rotationDeg = fixture.rotationDeg;
  r.lensOffsetM = profile.lensOffset;
  EXPECT_LT(axisMiss(r, f.panDeg, f.tiltDeg, point), 1e-3f);
  EXPECT_TRUE(profile.tiltDeg.contains(f.tiltDeg));
}

}  // namespace
}  // namespace haze
