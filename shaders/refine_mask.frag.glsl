// Marks the pixels whose half-resolution in-scattering the upsample cannot rebuild, so that the
// beam pass renders them again at full resolution (docs/rendering.md, "Refinement"). A smooth
// field (a beam's body, a soft edge: nearly linear over three texels) upsamples well; detail at
// the texel scale (a gobo's rings near the lens, a hard gate edge, a shadow's edge) does not.
// The measure is the relative curvature of the low-resolution values, |a - 2b + c| / (a + 2b +
// c), along rows, columns and both diagonals of the 3x3 texels around the pixel: 0 on a linear
// ramp, 1 at a lit texel beside dark ones. Marked pixels pass (stencil 1), the others are
// discarded.
#include "interface.h"
in vec2 vUv;
layout(binding = HAZE_UNIT_SCATTER) uniform sampler2D uScatter;
layout(location = HAZE_LOC_REFINE_CONTRAST) uniform float uContrast;
layout(location = HAZE_LOC_REFINE_FLOOR) uniform float uFloor;
layout(location = HAZE_FRAG_OUT) out float outMask;

float lum(ivec2 q, ivec2 size) {
  vec3 c = texelFetch(uScatter, clamp(q, ivec2(0), size - 1), 0).rgb;
  return dot(c, vec3(0.2126, 0.7152, 0.0722));
}

float curvature(float a, float b, float c) {
  float s = a + 2.0 * b + c;
  return s > 0.0 ? abs(a - 2.0 * b + c) / s : 0.0;
}

void main() {
  ivec2 size = textureSize(uScatter, 0);
  ivec2 q = ivec2(floor(vUv * vec2(size)));
  float v[9];
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) v[j * 3 + i] = lum(q + ivec2(i - 1, j - 1), size);
  float k = max(max(curvature(v[3], v[4], v[5]), curvature(v[1], v[4], v[7])),
                max(curvature(v[0], v[4], v[8]), curvature(v[2], v[4], v[6])));
  if (k < uContrast) discard;
  float brightest = max(max(max(v[0], v[1]), max(v[2], v[3])), max(max(v[4], v[5]), max(max(v[6], v[7]), v[8])));
  vec3 meanRgb = textureLod(uScatter, vec2(0.5), float(textureQueryLevels(uScatter) - 1)).rgb;
  if (brightest <= uFloor * dot(meanRgb, vec3(0.2126, 0.7152, 0.0722))) discard;
  outMask = 1.0;
}
