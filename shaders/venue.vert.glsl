// Venue vertices are already in world space (renderer/gpu_venue.cpp): one view-projection.
#include "interface.h"

layout(location = HAZE_ATTR_POSITION) in vec3 aPosition;
layout(location = HAZE_ATTR_NORMAL) in vec3 aNormal;
layout(location = HAZE_ATTR_UV) in vec2 aUv;
layout(location = HAZE_LOC_VIEW_PROJ) uniform mat4 uViewProj;
// The depth pre-pass and the lit pass must produce bit-identical depths (GL_EQUAL test).
invariant gl_Position;

out vec3 vPosition;
out vec3 vNormal;
out vec2 vUv;

void main() {
  vPosition = aPosition;
  vNormal = aNormal;
  vUv = aUv;
  gl_Position = uViewProj * vec4(aPosition, 1.0);
}
