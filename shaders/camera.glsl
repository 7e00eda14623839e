// The eye ray of a pixel and the scene distance along it (docs/physics.md, "What a pixel is").
#include "interface.h"

layout(location = HAZE_LOC_CAMERA_EYE) uniform vec3 uEye;
layout(location = HAZE_LOC_CAMERA_FORWARD) uniform vec3 uForward;    // unit view axis
layout(location = HAZE_LOC_CAMERA_RIGHT_TAN) uniform vec3 uRightTan; // right * tan(fov_x / 2)
layout(location = HAZE_LOC_CAMERA_UP_TAN) uniform vec3 uUpTan;       // up * tan(fov_y / 2)
layout(location = HAZE_LOC_CAMERA_NEAR_FAR) uniform vec2 uNearFar;   // projection's near, far (view depth, m)
layout(binding = HAZE_UNIT_SCENE_DEPTH) uniform sampler2D uSceneDepth;  // full-resolution depth buffer

// Unnormalised ray with dot(v, uForward) = 1, so a view depth z is the point eye + z * v.
vec3 eyeRay(vec2 ndc) { return uForward + ndc.x * uRightTan + ndc.y * uUpTan; }

// View depth of the first surface at a texture coordinate (far when nothing is hit).
float sceneViewDepth(vec2 uv) {
  float d = textureLod(uSceneDepth, uv, 0.0).r;
  float n = uNearFar.x, f = uNearFar.y;
  if (d >= 1.0) return f;
  return 2.0 * n * f / (f + n - (2.0 * d - 1.0) * (f - n));
}
