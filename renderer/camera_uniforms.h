// The camera as the full-screen and compute passes see it (shaders/camera.glsl): the eye, the
// view axis and the image plane's half-extents, so a pass can build any pixel's eye ray.
#pragma once

#include <glm/vec3.hpp>

#include "renderer/gl/gl.h"
#include "renderer/scene/frame_state.h"

namespace haze {

struct CameraBasis {
  glm::vec3 forward, right, up;
  float tanY, tanX;  // tangents of the half field of view, vertical and horizontal
};

CameraBasis cameraBasis(const CameraState& camera, float aspect);

// Sets camera.glsl's uniforms (locations 20 to 24) on a program.
void setCameraUniforms(GLuint program, const CameraState& camera, float aspect);

}  // namespace haze
