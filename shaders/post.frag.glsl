// Display encoding of the radiometric image (docs/physics.md, "Images"): optional bloom, exposure,
// then the ACES filmic fit of Narkowicz 2015 as the tone curve, then the sRGB transfer function.
// Bloom imitates the glare of an eye or a camera lens around bright beams and lamps: a fraction
// of each pixel's light is spread over a wide, heavy-tailed kernel (the mean of the radiance's
// mip levels 1 to 7, each smoothed by a tent), so the light is moved, not added. Display only:
// radiometric output never has it.
#include "interface.h"

in vec2 vUv;
layout(binding = HAZE_UNIT_RADIANCE) uniform sampler2D uRadiance;
layout(binding = HAZE_UNIT_RADIANCE_MIPS) uniform sampler2D uRadianceMips;  // the same image, trilinear sampler
layout(location = HAZE_LOC_POST_EXPOSURE) uniform float uExposure;  // multiplies cd/m^2 before the curve
layout(location = HAZE_LOC_POST_BLOOM) uniform float uBloom;        // fraction of the light spread, 0 = off
layout(location = HAZE_FRAG_OUT) out vec4 outColor;

vec3 aces(vec3 x) {
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
vec3 srgbEncode(vec3 c) {
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

#ifdef BLOOM  // a variant of its own: a CPU rasteriser would run the glare taps even when off
const int kBloomLevels = 7;

vec3 glare(vec2 uv) {
  vec3 sum = vec3(0.0);
  for (int level = 1; level <= kBloomLevels; ++level) {
    vec2 texel = 1.0 / vec2(textureSize(uRadianceMips, level));
    float lod = float(level);
    // A 3x3 tent of bilinear taps hides the blocks of the box-filtered mip level.
    vec3 c = textureLod(uRadianceMips, uv, lod).rgb * 4.0;
    c += (textureLod(uRadianceMips, uv + vec2(texel.x, 0.0), lod).rgb +
          textureLod(uRadianceMips, uv - vec2(texel.x, 0.0), lod).rgb +
          textureLod(uRadianceMips, uv + vec2(0.0, texel.y), lod).rgb +
          textureLod(uRadianceMips, uv - vec2(0.0, texel.y), lod).rgb) * 2.0;
    c += textureLod(uRadianceMips, uv + texel, lod).rgb + textureLod(uRadianceMips, uv - texel, lod).rgb +
         textureLod(uRadianceMips, uv + vec2(texel.x, -texel.y), lod).rgb +
         textureLod(uRadianceMips, uv + vec2(-texel.x, texel.y), lod).rgb;
    sum += c / 16.0;
  }
  return sum / float(kBloomLevels);
}
#endif

void main() {
  vec3 L = texture(uRadiance, vUv).rgb;
#ifdef BLOOM
  L = mix(L, glare(vUv), uBloom);
#endif
  outColor = vec4(srgbEncode(aces(L * uExposure)), 1.0);
}
