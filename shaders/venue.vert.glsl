// Venue vertices are already in world space (renderer/gpu_venue.cpp): one view-projection.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 0) uniform mat4 uViewProj;
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
