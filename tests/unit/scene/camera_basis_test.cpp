// The one camera basis (shows/scene/camera_basis.h): glm::lookAt's in the ordinary case, and
// the documented limit, never NaNs, when up is parallel to the view or the target is the eye.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include "shows/scene/camera_basis.h"

namespace haze {
namespace {

void expectNear(const glm::vec3& a, const glm::vec3& b, float tol, const char* what) {
  EXPECT_NEAR(a.x, b.x, tol) << what;
  EXPECT_NEAR(a.y, b.y, tol) << what;
  EXPECT_NEAR(a.z, b.z, tol) << what;
}

void expectOrthonormalRightHanded(const CameraBasis& b) {
  EXPECT_NEAR(glm::length(b.forward), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::length(b.right), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::length(b.up), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(b.forward, b.right), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(b.forward, b.up), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(b.right, b.up), 0.0f, 1e-5f);
  expectNear(glm::cross(b.forward, b.up), b.right, 1e-5f, "right = forward x up");
}

TEST(CameraBasis, AgreesWithGlmLookAtAndPerspective) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-10.0f, 10.0f);
  for (int trial = 0; trial < 200; ++trial) {
    CameraState c;
    c.position = {u(rng), u(rng), u(rng)};
    c.target = {u(rng), u(rng), u(rng)};
    c.up = glm::normalize(glm::vec3(0.3f * u(rng), 10.0f, 0.3f * u(rng)));
    c.fovYDeg = 20.0f + 3.0f * (u(rng) + 10.0f);
    const float aspect = 1.0f + 0.05f * (u(rng) + 10.0f);
    const CameraBasis b = cameraBasis(c, aspect);
    expectOrthonormalRightHanded(b);
    const glm::mat4 view = glm::lookAt(c.position, c.target, c.up);
    const glm::mat4 mine = cameraView(c);
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row) EXPECT_NEAR(mine[col][row], view[col][row], 1e-5f) << "view " << col << row;
    // glm::lookAt's rows are right, up and -forward.
    expectNear(b.right, {view[0][0], view[1][0], view[2][0]}, 1e-6f, "right");
    expectNear(b.up, {view[0][1], view[1][1], view[2][1]}, 1e-6f, "up");
    expectNear(b.forward, -glm::vec3(view[0][2], view[1][2], view[2][2]), 1e-6f, "forward");
    EXPECT_NEAR(b.tanY, std::tan(glm::radians(c.fovYDeg) * 0.5f), 1e-6f);
    EXPECT_NEAR(b.tanX, b.tanY * aspect, 1e-6f);
    const glm::mat4 vp = glm::perspective(glm::radians(c.fovYDeg), aspect, c.nearM, c.farM) * view;
    const glm::mat4 mineVp = cameraViewProjection(c, aspect);
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row)
        EXPECT_NEAR(mineVp[col][row], vp[col][row], 1e-4f * (1.0f + std::fabs(vp[col][row])));
  }
}

// Looking straight down with the default up: the limit of the eye moving towards +Z (the
// audience), so upstage (-Z) is at the top of the screen and +X to the right.
TEST(CameraBasis, StraightDownIsTheLimitFromTheAudienceSide) {
  CameraState down;
  down.position = {0.0f, 10.0f, 0.0f};
  down.target = {0.0f, 0.0f, 0.0f};
  const CameraBasis b = cameraBasis(down, 1.5f);
  expectOrthonormalRightHanded(b);
  expectNear(b.forward, {0, -1, 0}, 1e-6f, "forward");
  expectNear(b.right, {1, 0, 0}, 1e-6f, "right");
  expectNear(b.up, {0, 0, -1}, 1e-6f, "up");
  CameraState nudged = down;
  nudged.position.z += 1e-3f;
  const CameraBasis n = cameraBasis(nudged, 1.5f);
  expectNear(b.right, n.right, 1e-3f, "continuous from +Z: right");
  expectNear(b.up, n.up, 1e-3f, "continuous from +Z: up");
}

TEST(CameraBasis, StraightUpAndOtherUpsAreTheLimitFromPlusZ) {
  struct Case {
    glm::vec3 position, target, up;
  };
  const Case cases[] = {
      {{0, 0, 0}, {0, 5, 0}, {0, 1, 0}},      // straight up
      {{1, 2, 3}, {1, -4, 3}, {0, 3, 0}},     // straight down, up not unit
      {{0, 0, 0}, {3, 4, 0}, {0.6f, 0.8f, 0}},  // along a tilted up
      {{0, 0, 0}, {-3, -4, 0}, {0.6f, 0.8f, 0}},
  };
  for (const Case& k : cases) {
    CameraState c;
    c.position = k.position;
    c.target = k.target;
    c.up = k.up;
    const CameraBasis b = cameraBasis(c, 1.0f);
    expectOrthonormalRightHanded(b);
    CameraState nudged = c;
    nudged.position.z += 1e-3f;
    const CameraBasis n = cameraBasis(nudged, 1.0f);
    expectNear(b.right, n.right, 1e-3f, "right");
    expectNear(b.up, n.up, 1e-3f, "up");
  }
}

TEST(CameraBasis, ViewAlongZWithUpAlongZIsTheLimitFromPlusY) {
  CameraState c;
  c.position = {0, 0, 10};
  c.target = {0, 0, 0};
  c.up = {0, 0, 1};
  const CameraBasis b = cameraBasis(c, 1.0f);
  expectOrthonormalRightHanded(b);
  CameraState nudged = c;
  nudged.position.y += 1e-3f;
  const CameraBasis n = cameraBasis(nudged, 1.0f);
  expectNear(b.right, n.right, 1e-3f, "right");
  expectNear(b.up, n.up, 1e-3f, "up");
}

TEST(CameraBasis, DegenerateCamerasGiveFiniteMatrices) {
  CameraState zeroUp;
  zeroUp.up = glm::vec3(0.0f);
  CameraState targetAtEye;
  targetAtEye.target = targetAtEye.position;
  for (const CameraState& c : {zeroUp, targetAtEye}) {
    const CameraBasis b = cameraBasis(c, 1.0f);
    expectOrthonormalRightHanded(b);
    const glm::mat4 vp = cameraViewProjection(c, 1.0f);
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row) EXPECT_TRUE(std::isfinite(vp[col][row]));
  }
  expectNear(cameraBasis(targetAtEye, 1.0f).forward, {0, 0, -1}, 0.0f, "the default view direction");
}

}  // namespace
}  // namespace haze
