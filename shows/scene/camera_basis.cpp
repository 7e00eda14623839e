#include "shows/scene/camera_basis.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace haze {
namespace {

// Below this, |forward x up| / |up| (the sine of their angle) is too small for a direction.
constexpr float kParallelSine = 1e-6f;

}  // namespace

CameraBasis cameraBasis(const CameraState& c, float aspect) {
  CameraBasis b;
  const glm::vec3 view = c.target - c.position;
  b.forward = glm::length(view) > 0.0f ? glm::normalize(view) : glm::vec3(0.0f, 0.0f, -1.0f);
  glm::vec3 right = glm::cross(b.forward, c.up);
  const float upLength = glm::length(c.up);
  if (!(glm::length(right) > kParallelSine * upLength)) {
    // Moving the eye by a small e towards +Z turns forward by -e Z, and the ordinary basis then
    // tends to right = forward x (s Z), with s the sign of forward . up (see the header).
    const glm::vec3 towards = std::fabs(b.forward.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    const float s = glm::dot(b.forward, c.up) >= 0.0f ? 1.0f : -1.0f;
    right = glm::cross(b.forward, s * towards);
  }
  b.right = glm::normalize(right);
  b.up = glm::cross(b.right, b.forward);
  b.tanY = std::tan(glm::radians(c.fovYDeg) * 0.5f);
  b.tanX = b.tanY * aspect;
  return b;
}

glm::mat4 cameraView(const CameraState& c) {
  const CameraBasis b = cameraBasis(c, 1.0f);
  glm::mat4 m(1.0f);  // rows right, up, -forward, as glm::lookAt builds them
  for (int i = 0; i < 3; ++i) {
    m[i][0] = b.right[i];
    m[i][1] = b.up[i];
    m[i][2] = -b.forward[i];
  }
  m[3][0] = -glm::dot(b.right, c.position);
  m[3][1] = -glm::dot(b.up, c.position);
  m[3][2] = glm::dot(b.forward, c.position);
  return m;
}

glm::mat4 cameraProjection(const CameraState& c, float aspect) {
  return glm::perspective(glm::radians(c.fovYDeg), aspect, c.nearM, c.farM);
}

glm::mat4 cameraViewProjection(const CameraState& c, float aspect) {
  return cameraProjection(c, aspect) * cameraView(c);
}

}  // namespace haze
