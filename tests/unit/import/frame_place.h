// Where a point lands in a show camera's picture, for the tests of the MVR overview camera: the
// pinhole of docs/physics.md written out here rather than taken from the renderer.
#pragma once

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>

#include "shows/show.h"

namespace haze {

// x and y within -1..1 when p is inside the frame of `cam` at the aspect width / height (16:9,
// the one the import fits the rig to); far outside for a point behind the camera.
inline glm::vec2 framePlace(const CameraDef& cam, const glm::vec3& p, float aspect = 16.0f / 9.0f) {
  const glm::vec3 f = glm::normalize(cam.target - cam.position);
  const glm::vec3 r = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0)));
  const glm::vec3 u = glm::cross(r, f);
  const glm::vec3 d = p - cam.position;
  const float z = glm::dot(d, f);
  if (z <= 0.0f) return {1e9f, 1e9f};
  const float t = std::tan(glm::radians(cam.fovYDeg) / 2.0f);
  return {glm::dot(d, r) / (z * t * aspect), glm::dot(d, u) / (z * t)};
}

}  // namespace haze
