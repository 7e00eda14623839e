#include "renderer/camera_uniforms.h"

#include <glm/gtc/type_ptr.hpp>

#include "shaders/interface.h"

namespace haze {

void setCameraUniforms(GLuint prog, const CameraState& c, float aspect) {
  const CameraBasis b = cameraBasis(c, aspect);
  glProgramUniform3fv(prog, HAZE_LOC_CAMERA_EYE, 1, glm::value_ptr(c.position));
  glProgramUniform3fv(prog, HAZE_LOC_CAMERA_FORWARD, 1, glm::value_ptr(b.forward));
  const glm::vec3 rt = b.right * b.tanX, ut = b.up * b.tanY;
  glProgramUniform3fv(prog, HAZE_LOC_CAMERA_RIGHT_TAN, 1, glm::value_ptr(rt));
  glProgramUniform3fv(prog, HAZE_LOC_CAMERA_UP_TAN, 1, glm::value_ptr(ut));
  glProgramUniform2f(prog, HAZE_LOC_CAMERA_NEAR_FAR, c.nearM, c.farM);
}

}  // namespace haze
