// Surfaces lit by every beam, per physics.md: two-sided Lambert with I_eff, V, cosine,
// exp(-sigma_t r) / r^2, plus ambient and emission, then attenuated by exp(-sigma_t T) to the eye.
#include "beams.glsl"

in vec3 vPosition;
in vec3 vNormal;
in vec2 vUv;

layout(location = 1) uniform vec3 uEye;
layout(location = 2) uniform float uSigmaT;
layout(location = 3) uniform vec3 uAmbient;
layout(location = 4) uniform vec4 uBaseColor;
layout(location = 5) uniform vec3 uEmissive;
layout(location = 6) uniform int uHasBaseTexture;
layout(location = 7) uniform int uHasEmissiveTexture;
layout(location = 8) uniform int uBeamCount;
layout(binding = 3) uniform sampler2D uBaseTexture;
layout(binding = 4) uniform sampler2D uEmissiveTexture;

layout(location = 0) out vec4 outRadiance;

void main() {
  vec3 toEye = uEye - vPosition;
  float T = length(toEye);
  vec3 n = normalize(vNormal);
  if (dot(n, toEye) < 0.0) n = -n;  // two-sided: the normal faces the eye
  vec3 albedo = uBaseColor.rgb;
  if (uHasBaseTexture != 0) albedo *= texture(uBaseTexture, vUv).rgb;
  vec3 emission = uEmissive;
  if (uHasEmissiveTexture != 0) emission *= texture(uEmissiveTexture, vUv).rgb;

  vec3 irradiance = vec3(0.0);
  for (int i = 0; i < uBeamCount; ++i) {
    // Most beams miss most pixels: test the cone with two loads before anything else.
    vec4 lens = beams[i].lensPos;
    vec3 d = vPosition - lens.xyz;
    if (dot(d, beams[i].zb.xyz) <= lens.w * length(d)) continue;
    vec3 wl;
    float r;
    vec3 I = beamIntensity(beams[i], vPosition, wl, r);
    float cosine = dot(n, -wl);
    if (cosine <= 0.0 || I == vec3(0.0)) continue;
    // Shadow lookups from a point nudged off the surface, by about a shadow texel at distance r.
    float v = beamVisibility(beams[i], vPosition + n * (0.0015 * r));
    irradiance += I * (v * cosine * exp(-uSigmaT * r) / (r * r));
  }
  vec3 L = albedo / PI * irradiance + albedo * uAmbient + emission;
  outRadiance = vec4(L * exp(-uSigmaT * T), 1.0);
}
