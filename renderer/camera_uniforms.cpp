#include "renderer/camera_uniforms.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace haze {

CameraBasis cameraBasis(const CameraState& c, float aspect) {
  CameraBasis b;
  b.forward = glm::normalize(c.target - c.position);
  b.right = glm::normalize(glm::cross(b.forward, c.up));
  b.up = glm::cross(b.right, b.forward);
  b.tanY = std::tan(glm::radians(c.fovYDeg) * 0.5f);
  b.tanX = b.tanY * aspect;
  return b;
}

void setCameraUniforms(GLuint prog, const CameraState& c, float aspect) {
  const CameraBasis b = cameraBasis(c, aspect);
  glProgramUniform3fv(prog, 20, 1, glm::value_ptr(c.position));
  glProgramUniform3fv(prog, 21, 1, glm::value_ptr(b.forward));
  const glm::vec3 rt = b.right * b.tanX, ut = b.up * b.tanY;
  glProgramUniform3fv(prog, 22, 1, glm::value_ptr(rt));
  glProgramUniform3fv(prog, 23, 1, glm::value_ptr(ut));
  glProgramUniform2f(prog, 24, c.nearM, c.farM);
}

}  // namespace haze
