// The lens discs of docs/physics.md, "The lens": instance i is beam i's disc of radius r_lens,
// drawn as the square around it in the disc's own plane (so rasterised depth is the disc's
// depth); the fragment shader cuts the circle out.
#include "beams.glsl"

layout(location = HAZE_LOC_LENS_VIEW_PROJ) uniform mat4 uViewProj;

out vec2 vDisc;     // (x_b, y_b) coordinates in units of r_lens
out vec3 vPosition;
flat out int vBeam;

void main() {
  Beam b = beams[gl_InstanceID];
  vec2 c = vec2((gl_VertexID & 1) != 0 ? 1.0 : -1.0, (gl_VertexID & 2) != 0 ? 1.0 : -1.0);
  vDisc = c;
  vBeam = gl_InstanceID;
  vPosition = b.lensPos.xyz + b.lens.x * (c.x * b.xb.xyz + c.y * b.yb.xyz);
  gl_Position = uViewProj * vec4(vPosition, 1.0);
}
