// A particle's kernel: (1 - rho^2)^2 over a disc of radius R pixels, whose integral is pi R^2 / 3
// (the vertex shader's peak has that normalisation), added onto the radiance.
#include "interface.h"

flat in vec3 vPeak;
layout(location = HAZE_FRAG_OUT) out vec4 outRadiance;

void main() {
  vec2 c = gl_PointCoord * 2.0 - 1.0;
  float rho2 = dot(c, c);
  if (rho2 >= 1.0) discard;
  float w = 1.0 - rho2;
  outRadiance = vec4(vPeak * (w * w), 0.0);
}
