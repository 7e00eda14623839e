// Beams as every lighting shader sees them: the storage buffer written by
// renderer/beam_resources.cpp, the light-map array (I * gobo * gate over the
// (u, v) plane of docs/physics.md) and the shadow-map array (depth from each lens). struct Beam is
// declared in interface.h, shared with the C++ that fills the buffer.
#include "interface.h"

const float PI = 3.14159265358979323846;

layout(std430, binding = HAZE_SSBO_BEAMS) readonly buffer Beams { Beam beams[]; };
layout(binding = HAZE_UNIT_LIGHT_MAPS) uniform sampler2DArray uLightMaps;
layout(binding = HAZE_UNIT_SHADOW_MAPS) uniform sampler2DArrayShadow uShadowMaps;

// I_eff (cd per channel) towards world point x, without visibility (docs/physics.md); wl is the
// unit direction the light travels, r the distance from the lens.
vec3 beamIntensity(Beam b, vec3 x, out vec3 wl, out float r) {
  vec3 d = x - b.lensPos.xyz;
  r = max(length(d), 1e-6);
  wl = d / r;
  float cz = dot(wl, b.zb.xyz);
  if (cz <= b.lensPos.w) return vec3(0.0);
  vec2 uv = vec2(dot(wl, b.xb.xyz), dot(wl, b.yb.xyz)) / cz * b.xb.w;
  float cd = texture(uLightMaps, vec3(uv * 0.5 + 0.5, b.yb.w)).r;
  return cd * b.color.rgb;
}

// V(x) in the medium: one hardware 2x2 PCF tap (shafts are soft; the surfaces get five).
float beamVisibilityVolume(Beam b, vec3 x) {
  vec4 c = b.shadowViewProj * vec4(x, 1.0);
  if (c.w <= 0.0) return 1.0;
  vec3 s = c.xyz / c.w * 0.5 + 0.5;
  if (any(lessThan(s.xy, vec2(0.0))) || any(greaterThan(s.xy, vec2(1.0)))) return 1.0;
  return texture(uShadowMaps, vec4(s.xy, b.zb.w, s.z));
}

// V(x): 1 where the lens sees x, 0 in shadow; hardware 2x2 PCF plus four taps around it.
float beamVisibility(Beam b, vec3 x) {
  vec4 c = b.shadowViewProj * vec4(x, 1.0);
  if (c.w <= 0.0) return 1.0;
  vec3 s = c.xyz / c.w * 0.5 + 0.5;
  if (any(lessThan(s.xy, vec2(0.0))) || any(greaterThan(s.xy, vec2(1.0)))) return 1.0;
  vec2 texel = 1.0 / vec2(textureSize(uShadowMaps, 0).xy);
  float v = texture(uShadowMaps, vec4(s.xy, b.zb.w, s.z)) * 0.5;
  v += texture(uShadowMaps, vec4(s.xy + vec2(0.5, 0.5) * texel, b.zb.w, s.z)) * 0.125;
  v += texture(uShadowMaps, vec4(s.xy + vec2(-0.5, 0.5) * texel, b.zb.w, s.z)) * 0.125;
  v += texture(uShadowMaps, vec4(s.xy + vec2(0.5, -0.5) * texel, b.zb.w, s.z)) * 0.125;
  v += texture(uShadowMaps, vec4(s.xy + vec2(-0.5, -0.5) * texel, b.zb.w, s.z)) * 0.125;
  return v;
}
