// The camera as the full-screen and compute passes see it (shaders/camera.glsl): the eye, the
// view axis and the image plane's half-extents, so a pass can build any pixel's eye ray.
#pragma once

#include "renderer/gl/gl.h"
#include "shows/scene/camera_basis.h"
#include "shows/scene/frame_state.h"

namespace haze {

// Sets camera.glsl's uniforms (HAZE_LOC_CAMERA_*) on a program.
void setCameraUniforms(GLuint program, const CameraState& camera, float aspect);

}  // namespace haze
