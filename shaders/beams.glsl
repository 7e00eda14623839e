// Beams as every lighting shader sees them: the storage buffer written by
// renderer/beam_resources.cpp, the light-map array (I * gobo * gate over the
// (u, v) plane of docs/physics.md) and the shadow-map array (depth from each lens). struct Beam is
// declared in interface.h, shared with the C++ that fills the buffer.
#include "interface.h"

const float PI = 3.14159265358979323846;

layout(std430, binding = HAZE_SSBO_BEAMS) readonly buffer Beams { Beam beams[]; };
layout(binding = HAZE_UNIT_LIGHT_MAPS) uniform sampler2DArray uLightMaps;
layout(binding = HAZE_UNIT_SHADOW_MAPS) uniform sampler2DArrayShadow uShadowMaps;
// The same shadow maps through a sampler without compare mode (nearest): the raw depths that
// the soft shadows' blocker search averages.
layout(binding = HAZE_UNIT_SHADOW_DEPTH) uniform sampler2DArray uShadowDepths;
layout(location = HAZE_LOC_SOFT_SHADOWS) uniform int uSoftShadows;  // 0: V is the point test from the lens centre
// The shadow maps' least depths over blocks (renderer/scene/depth_pyramid.h), the pyramid's levels
// side by side in one level of each layer (level 0 at the origin, level m >= 1 at x = n_0 above
// levels 1..m-1): a texel fetch's mip level may not differ from pixel to pixel on llvmpipe, which
// takes one level per quad. Level m texel i covers the map's texels [i c, (i + 2) c),
// c = 2^(m + HAZE_SHADOW_MIN_FIRST_SHIFT).
layout(binding = HAZE_UNIT_SHADOW_MIN) uniform sampler2DArray uShadowMin;
layout(location = HAZE_LOC_SHADOW_MIN_ON) uniform int uShadowMinOn;  // 0: every lookup takes all its taps

// The rotation of the soft shadows' tap pattern, a fraction of a turn: the caller seeds it per
// pixel (its noise), and every soft lookup moves it on by the golden ratio, so the samples of
// one walk through the haze each see the pattern turned differently and their mean converges.
float gShadowTurn = 0.0;

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

// Whether every shadow-map texel that a lookup within `radius` (map units) of s.xy can read, with
// a texel of margin for the sampler's rounding, lies at depth s.z or beyond: then every tap there
// is lit (no blocker, every compare passes) and V is exactly 1, from one texel of the pyramid
// instead of the taps. Most lit surface points are unshadowed; the taps cost most of the surfaces.
bool surelyLit(Beam b, vec3 s, float radius) {
  if (uShadowMinOn == 0) return false;
  float size = float(textureSize(uShadowDepths, 0).x);
  ivec2 lo = ivec2(clamp(floor((s.xy - radius) * size) - 1.0, 0.0, size - 1.0));
  ivec2 hi = ivec2(clamp(floor((s.xy + radius) * size) + 1.0, 0.0, size - 1.0));
  int span = max(hi.x - lo.x, hi.y - lo.y) + 1;
  // The level whose cells are at least span texels: the run [lo, hi] then lies in one texel's
  // two cells. The top level's one texel covers the whole map.
  int n0 = textureSize(uShadowMin, 0).y;
  int m = min(max(0, findMSB(span - 1) + 1 - HAZE_SHADOW_MIN_FIRST_SHIFT), findMSB(n0));
  int cell = 1 << (m + HAZE_SHADOW_MIN_FIRST_SHIFT);
  ivec2 origin = ivec2(m > 0 ? n0 : 0, 0);
  for (int k = 1; k < m; ++k) origin.y += max(1, n0 >> k);
  ivec2 t = origin + min(lo / cell, ivec2(max(1, n0 >> m) - 1));
  return texelFetch(uShadowMin, ivec3(t, int(b.zb.w)), 0).r >= s.z;
}

// Soft shadows (docs/physics.md, "Soft shadows"; docs/rendering.md, "Soft shadows"): the
// fraction of the lens disc (radius b.lens.x, perpendicular to z_b) that the point with shadow
// clip coordinates c sees, by percentage-closer soft shadows (Fernando 2005). The disc seen
// from the point, projected onto a plane of blockers at axial depth w_b, is a disc of radius
// r_lens (1 / w_b - 1 / w_r) in tan(angle) units around the point's own direction (the shadow
// map's planes of equal depth are parallel to the lens, so this is exact for a flat blocker):
// a blocker search over the region where blockers down to w_r / 3 could hide part of the disc
// gives the mean 1 / w_b, then PCF over that disc gives the visible fraction. Taps lie on a
// Vogel spiral turned by gShadowTurn.
float softVisibility(Beam b, vec4 c, int blockerTaps, int filterTaps) {
  vec3 s = c.xyz / c.w * 0.5 + 0.5;
  mat4 m = b.shadowViewProj;
  // Shadow-map u per unit of tan(angle) off the axis: 0.5 / tan(fov / 2), half the length of
  // the matrix's first row (a rotation times the projection's P00).
  float uvPerTan = 0.5 * length(vec3(m[0][0], m[1][0], m[2][0]));
  // Window depth d and axial depth w: 2 d - 1 = -P22 + P32 / w. Row 3 of the matrix is minus
  // the view's z row, row 2 is -P22 times row 3 plus P32 in the last column.
  vec3 rz = vec3(m[0][2], m[1][2], m[2][2]), rw = vec3(m[0][3], m[1][3], m[2][3]);
  float p22 = -dot(rz, rw) / dot(rw, rw);
  float invP32 = 1.0 / (m[3][2] + p22 * m[3][3]);
  float invWr = 1.0 / c.w;
  float k = b.lens.x * uvPerTan;  // the disc's projected radius in map units per (1 / w_b - 1 / w_r)
  float texel = 1.0 / float(textureSize(uShadowDepths, 0).x);
  float searchR = 2.0 * k * invWr;  // blockers from w_r / 3 to w_r
  float turn = 6.28318531 * gShadowTurn;
  gShadowTurn = fract(gShadowTurn + 0.618034);
  // A CPU rasteriser (llvmpipe) runs both sides of a branch for a block of pixels, masked; only a
  // loop ends early, once no pixel of the block wants another turn. So the taps are loops whose
  // count is 0 where they cannot change V (surely lit; no blocker; a penumbra under a texel).
  int searchTaps = surelyLit(b, s, searchR) ? 0 : blockerTaps;
  const float GOLDEN = 2.39996323;
  float blockers = 0.0, sumInvW = 0.0;
  for (int i = 0; i < searchTaps; ++i) {
    float a = float(i) * GOLDEN + turn;
    vec2 uv = s.xy + searchR * sqrt((float(i) + 0.5) / float(blockerTaps)) * vec2(cos(a), sin(a));
    float d = texture(uShadowDepths, vec3(uv, b.zb.w)).r;
    if (d < s.z) {
      blockers += 1.0;
      sumInvW += (2.0 * d - 1.0 + p22) * invP32;
    }
  }
  if (blockers == 0.0) return 1.0;
  float filterR = k * max(sumInvW / blockers - invWr, 0.0);
  if (filterR < texel) return texture(uShadowMaps, vec4(s.xy, b.zb.w, s.z));  // as sharp as the map
  float v = 0.0;
  turn += 1.0;  // not the search's pattern
  int taps = blockers == 0.0 || filterR < texel ? 0 : filterTaps;
  for (int i = 0; i < taps; ++i) {
    float a = float(i) * GOLDEN + turn;
    vec2 uv = s.xy + filterR * sqrt((float(i) + 0.5) / float(filterTaps)) * vec2(cos(a), sin(a));
    v += texture(uShadowMaps, vec4(uv, b.zb.w, s.z));
  }
  return v / float(filterTaps);
}

// Taps of the soft shadows: the surfaces' one lookup per pixel and beam can afford more than
// each sample of a walk through the haze, whose many samples average their patterns.
const int SOFT_SURFACE_BLOCKER_TAPS = 16;
const int SOFT_SURFACE_FILTER_TAPS = 16;
const int SOFT_VOLUME_BLOCKER_TAPS = 4;
const int SOFT_VOLUME_FILTER_TAPS = 4;

// V in the medium from the point's shadow clip coordinates c: one hardware 2x2 PCF tap (shafts
// are soft; the surfaces get five), or the soft shadows' few taps.
float beamVisibilityClip(Beam b, vec4 c) {
  if (c.w <= 0.0) return 1.0;
  vec3 s = c.xyz / c.w * 0.5 + 0.5;
  if (any(lessThan(s.xy, vec2(0.0))) || any(greaterThan(s.xy, vec2(1.0)))) return 1.0;
  if (uSoftShadows != 0 && b.lens.x > 0.0)
    return softVisibility(b, c, SOFT_VOLUME_BLOCKER_TAPS, SOFT_VOLUME_FILTER_TAPS);
  return texture(uShadowMaps, vec4(s.xy, b.zb.w, s.z));
}

// V(x) in the medium.
float beamVisibilityVolume(Beam b, vec3 x) { return beamVisibilityClip(b, b.shadowViewProj * vec4(x, 1.0)); }

// V(x): 1 where the lens sees x, 0 in shadow; hardware 2x2 PCF plus four taps around it, or
// the soft shadows' visible fraction of the disc.
float beamVisibility(Beam b, vec3 x) {
  vec4 c = b.shadowViewProj * vec4(x, 1.0);
  if (c.w <= 0.0) return 1.0;
  vec3 s = c.xyz / c.w * 0.5 + 0.5;
  if (any(lessThan(s.xy, vec2(0.0))) || any(greaterThan(s.xy, vec2(1.0)))) return 1.0;
  if (uSoftShadows != 0 && b.lens.x > 0.0)
    return softVisibility(b, c, SOFT_SURFACE_BLOCKER_TAPS, SOFT_SURFACE_FILTER_TAPS);
  vec2 texel = 1.0 / vec2(textureSize(uShadowMaps, 0).xy);
  if (surelyLit(b, s, 1.5 * texel.x)) return 1.0;  // the taps' 2x2 footprints reach a texel and a half
  float v = texture(uShadowMaps, vec4(s.xy, b.zb.w, s.z)) * 0.5;
  v += texture(uShadowMaps, vec4(s.xy + vec2(0.5, 0.5) * texel, b.zb.w, s.z)) * 0.125;
  v += texture(uShadowMaps, vec4(s.xy + vec2(-0.5, 0.5) * texel, b.zb.w, s.z)) * 0.125;
  v += texture(uShadowMaps, vec4(s.xy + vec2(0.5, -0.5) * texel, b.zb.w, s.z)) * 0.125;
  v += texture(uShadowMaps, vec4(s.xy + vec2(-0.5, -0.5) * texel, b.zb.w, s.z)) * 0.125;
  return v;
}
