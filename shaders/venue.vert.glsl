// Venue vertices are already in world space (renderer/gpu_venue.cpp): one view-projection, and
// the model matrix stays the identity. A fixture body's mesh (renderer/gpu_bodies.cpp) is stored
// once in its part's frame and placed per draw by uModel (a rotation and a translation).
#include "interface.h"

layout(location = HAZE_ATTR_POSITION) in vec3 aPosition;
layout(location = HAZE_ATTR_NORMAL) in vec3 aNormal;
layout(location = HAZE_ATTR_UV) in vec2 aUv;
layout(location = HAZE_LOC_VIEW_PROJ) uniform mat4 uViewProj;
layout(location = HAZE_LOC_MODEL) uniform mat4 uModel = mat4(1.0);
// Shadow maps, the G-buffer and the beam pass's depth reads must agree on the venue's depths to the bit.
invariant gl_Position;

out vec3 vPosition;
out vec3 vNormal;
out vec2 vUv;

void main() {
  const vec4 world = uModel * vec4(aPosition, 1.0);
  vPosition = world.xyz;
  vNormal = mat3(uModel) * aNormal;
  vUv = aUv;
  gl_Position = uViewProj * world;
}
