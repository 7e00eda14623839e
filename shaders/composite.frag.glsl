// Adds the scattering buffer (possibly at lower resolution) onto the radiance target, with a
// depth-aware upsample: of the four nearest low-resolution samples, those whose scene depth is
// close to this pixel's weigh most, so beams do not bleed across silhouettes. Pixels the
// refinement rendered again at full resolution (refine_mask.frag.glsl) take that value instead.
#include "camera.glsl"

in vec2 vUv;
layout(binding = HAZE_UNIT_SCATTER) uniform sampler2D uScatter;             // accumulated in-scattering
layout(binding = HAZE_UNIT_SCATTER_DEPTH) uniform sampler2D uScatterDepth;  // view depth of each scattering texel
layout(location = HAZE_LOC_COMPOSITE_SCALE) uniform float uScale;           // 1 / accumulated frames
layout(location = HAZE_LOC_COMPOSITE_UPSAMPLE) uniform int uUpsample;       // 0: same resolution
layout(location = HAZE_LOC_COMPOSITE_REFINE) uniform int uRefine;           // 1: refined pixels are in uFine
layout(binding = HAZE_UNIT_SCATTER_FINE) uniform sampler2D uFine;           // full resolution, where refined
layout(binding = HAZE_UNIT_REFINE_MASK) uniform sampler2D uMask;            // 1 where refined

layout(location = HAZE_FRAG_OUT) out vec4 outAdd;

void main() {
  if (uUpsample == 0) {
    outAdd = vec4(texture(uScatter, vUv).rgb * uScale, 0.0);
    return;
  }
  if (uRefine != 0 && texture(uMask, vUv).r > 0.5) {
    outAdd = vec4(texture(uFine, vUv).rgb * uScale, 0.0);
    return;
  }
  vec2 size = vec2(textureSize(uScatter, 0));
  vec2 p = vUv * size - 0.5;
  vec2 f = fract(p);
  ivec2 base = ivec2(floor(p));
  float z = sceneViewDepth(vUv);
  vec3 sum = vec3(0.0);
  float wsum = 0.0;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      ivec2 q = clamp(base + ivec2(i, j), ivec2(0), ivec2(size) - 1);
      float bilinear = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
      float zq = texelFetch(uScatterDepth, q, 0).r;
      float w = bilinear / (1e-3 + abs(zq - z) / max(z, 1e-3));
      sum += texelFetch(uScatter, q, 0).rgb * w;
      wsum += w;
    }
  outAdd = vec4(sum / max(wsum, 1e-12) * uScale, 0.0);
}
