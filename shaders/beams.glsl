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
#if defined(STATIC_FEATURES) && !defined(SOFT_SHADOWS)
#define SOFT_SHADOWS_ON false  // compiled out (shaders/interface.h, "Static features")
#else
#define SOFT_SHADOWS_ON (uSoftShadows != 0)
#endif
// The shadow maps' least depths over blocks (shows/scene/depth_pyramid.h), the pyramid's levels
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

// Whether every shadow-map texel in the box [lo, hi] (map units), with a texel of margin for
// the sampler's rounding, lies at or beyond the depth its taps compare against: then every tap
// there is lit (no blocker, every compare passes) and V is exactly 1, from one texel of the
// pyramid instead of the taps. Most lit points are unshadowed; the taps cost most of the
// surfaces and of the walks. A tap at map point u (which lies in the box) compares against
// z + dot(grad, u - centre), the receiver's plane through the lookup's point (grad 0 in the
// medium, see visibilityAt), so the test takes the plane's highest value over the box.
bool surelyLitBox(Beam b, vec2 lo, vec2 hi, float z, vec2 centre, vec2 grad) {
  if (uShadowMinOn == 0) return false;
  float size = float(textureSize(uShadowDepths, 0).x);
  ivec2 l = ivec2(clamp(floor(lo * size) - 1.0, 0.0, size - 1.0));
  ivec2 h = ivec2(clamp(floor(hi * size) + 1.0, 0.0, size - 1.0));
  int span = max(h.x - l.x, h.y - l.y) + 1;
  // The level whose cells are at least span texels: the run [l, h] then lies in one texel's
  // two cells. The top level's one texel covers the whole map.
  int n0 = textureSize(uShadowMin, 0).y;
  int m = min(max(0, findMSB(span - 1) + 1 - HAZE_SHADOW_MIN_FIRST_SHIFT), findMSB(n0));
  // Level m lies above levels 1..m-1 of heights n0 >> k (each at least 2 here, as m is at most
  // log2 n0): their sum in closed form, as sum_{k >= 1} (n >> k) = n - popcount(n), so that the
  // lookup has no loop (llvmpipe runs a loop as long as the block's longest pixel needs).
  int q = n0 >> max(m - 1, 0);
  ivec2 origin = ivec2(m > 0 ? n0 : 0, m > 1 ? (n0 - bitCount(n0)) - (q - bitCount(q)) : 0);
  // A shift, not a division: llvmpipe divides integer vectors one lane at a time.
  ivec2 cell = min(l >> (m + HAZE_SHADOW_MIN_FIRST_SHIFT), ivec2(max(1, n0 >> m) - 1));
  // The plane's rise over the box, at the corner where it is highest.
  vec2 rise = max(grad * (lo - centre), grad * (hi - centre));
  return texelFetch(uShadowMin, ivec3(origin + cell, int(b.zb.w)), 0).r >= z + rise.x + rise.y;
}

bool surelyLitBox(Beam b, vec2 lo, vec2 hi, float z) { return surelyLitBox(b, lo, hi, z, lo, vec2(0.0)); }

// What the soft shadows need of a beam, worked out once per pixel and beam: the compiler does
// not hoist it out of a walk's loop, and every sample would redo it.
struct SoftShadowSetup {
  float k;       // the disc's projected radius in map units per (1 / w_b - 1 / w_r)
  float p22;     // window depth d and axial depth w: 2 d - 1 = -p22 + 1 / (invP32 w)
  float invP32;
  float texel;   // one shadow-map texel in map units
};

SoftShadowSetup softShadowSetup(Beam b) {
  mat4 m = b.shadowViewProj;
  SoftShadowSetup ss;
  // Shadow-map u per unit of tan(angle) off the axis: 0.5 / tan(fov / 2), half the length of
  // the matrix's first row (a rotation times the projection's P00).
  ss.k = b.lens.x * 0.5 * length(vec3(m[0][0], m[1][0], m[2][0]));
  // Row 3 of the matrix is minus the view's z row, row 2 is -P22 times row 3 plus P32 in the
  // last column.
  vec3 rz = vec3(m[0][2], m[1][2], m[2][2]), rw = vec3(m[0][3], m[1][3], m[2][3]);
  ss.p22 = -dot(rz, rw) / dot(rw, rw);
  ss.invP32 = 1.0 / (m[3][2] + ss.p22 * m[3][3]);
  ss.texel = 1.0 / float(textureSize(uShadowDepths, 0).x);
  return ss;
}

// Taps of the soft shadows: the surfaces' one lookup per pixel and beam can afford more than
// each sample of a walk through the haze, whose many samples average their patterns.
const int SOFT_SURFACE_BLOCKER_TAPS = 16;
const int SOFT_SURFACE_FILTER_TAPS = 16;
const int SOFT_VOLUME_BLOCKER_TAPS = 4;
const int SOFT_VOLUME_FILTER_TAPS = 4;

// Tap i of a pattern lies at angle i GOLDEN + turn: each tap's direction is the last one's
// turned by GOLDEN (a complex product), so a lookup takes one sine and cosine, not one per tap.
const vec2 GOLDEN_TURN = vec2(-0.73736888, 0.67549029);  // (cos, sin) of 2.39996323
vec2 nextTap(vec2 dir) { return vec2(dir.x * GOLDEN_TURN.x - dir.y * GOLDEN_TURN.y, dir.x * GOLDEN_TURN.y + dir.y * GOLDEN_TURN.x); }

// V at the point with shadow clip coordinates c. With soft shadows (SOFT_SHADOWS and a lens of
// some size) the fraction of the lens disc (radius b.lens.x, perpendicular to z_b) that the point
// sees, by percentage-closer soft shadows (Fernando 2005; docs/physics.md, "Soft shadows";
// docs/rendering.md, "Soft shadows"): the disc seen from the point, projected onto a plane of
// blockers at axial depth w_b, is a disc of radius r_lens (1 / w_b - 1 / w_r) in tan(angle)
// units around the point's own direction (the shadow map's planes of equal depth are parallel
// to the lens, so this is exact for a flat blocker): a blocker search over the region where
// blockers down to w_r / 3 could hide part of the disc gives the mean 1 / w_b, then PCF over
// that disc gives the visible fraction; a penumbra under a texel takes one hardware tap. Taps
// lie on a Vogel spiral turned by gShadowTurn. Otherwise the hard shadow of the lens centre:
// one hardware 2x2 PCF tap (hardTaps 1: shafts are soft) or that tap and four around it
// (hardTaps 5: the surfaces).
//
// A CPU rasteriser (llvmpipe) runs both sides of a branch for a block of pixels, masked, texture
// lookups included; only a loop ends early, once no pixel of the block wants another turn (it
// tests at the end of the body, so a loop no pixel wants runs its body once, masked: one tap,
// not sixteen). So every lookup here is in a loop whose count is 0 where it cannot change V
// (surely lit, no blocker, the other kind of shadow), and the one return is at the end.
float visibilityAt(Beam b, SoftShadowSetup ss, vec4 c, vec2 grad, int blockerTaps, int filterTaps, int hardTaps) {
  vec3 s = c.xyz / c.w * 0.5 + 0.5;
  bool inMap = c.w > 0.0 && all(greaterThanEqual(s.xy, vec2(0.0))) && all(lessThanEqual(s.xy, vec2(1.0)));
  bool soft = SOFT_SHADOWS_ON && b.lens.x > 0.0;
  float invWr = 1.0 / c.w;
  float searchR = soft ? 2.0 * ss.k * invWr : 1.5 * ss.texel;  // soft: blockers from w_r / 3 to w_r
  float turn = 6.28318531 * gShadowTurn;
  gShadowTurn = fract(gShadowTurn + 0.618034);
  bool lit = !inMap || surelyLitBox(b, s.xy - searchR, s.xy + searchR, s.z, s.xy, grad);
  float blockers = 0.0, sumInvW = 0.0;
  vec2 dir = vec2(cos(turn), sin(turn));
  for (int i = 0; i < (soft && !lit ? blockerTaps : 0); ++i) {
    vec2 uv = s.xy + searchR * sqrt((float(i) + 0.5) / float(blockerTaps)) * dir;
    dir = nextTap(dir);
    float d = texture(uShadowDepths, vec3(uv, b.zb.w)).r;
    if (d < s.z + dot(grad, uv - s.xy)) {
      blockers += 1.0;
      sumInvW += (2.0 * d - 1.0 + ss.p22) * ss.invP32;
    }
  }
  float filterR = blockers > 0.0 ? ss.k * max(sumInvW / blockers - invWr, 0.0) : 0.0;
  bool sharp = filterR < ss.texel;  // as sharp as the map: one tap
  int taps = soft ? (blockers == 0.0 ? 0 : (sharp ? 1 : filterTaps)) : (lit ? 0 : hardTaps);
  float v = 0.0;
  if (soft) {
    // Not the search's pattern: turned one radian further, (cos 1, sin 1).
    dir = vec2(cos(turn), sin(turn));
    dir = vec2(dir.x * 0.54030231 - dir.y * 0.84147098, dir.x * 0.84147098 + dir.y * 0.54030231);
  }
  float r = soft && !sharp ? filterR : 0.0;
  for (int i = 0; i < taps; ++i) {
    // Soft: the Vogel spiral over the filter disc. Hard: the centre (weight 1/2), then the
    // four diagonal half-texel neighbours (1/8 each).
    vec2 hardOffset = i == 0 ? vec2(0.0) : (vec2(i == 1 || i == 3 ? 0.5 : -0.5, i <= 2 ? 0.5 : -0.5) * ss.texel);
    vec2 uv = s.xy + (soft ? r * sqrt((float(i) + 0.5) / float(filterTaps)) * dir : hardOffset);
    dir = nextTap(dir);
    float w = soft || taps == 1 ? 1.0 : (i == 0 ? 0.5 : 0.125);
    v += w * texture(uShadowMaps, vec4(uv, b.zb.w, s.z + dot(grad, uv - s.xy)));
  }
  return taps == 0 ? 1.0 : (soft ? v / float(taps) : v);
}

// V in the medium from the point's shadow clip coordinates c.
float beamVisibilityClip(Beam b, SoftShadowSetup ss, vec4 c) {
  return visibilityAt(b, ss, c, vec2(0.0), SOFT_VOLUME_BLOCKER_TAPS, SOFT_VOLUME_FILTER_TAPS, 1);
}

float beamVisibilityClip(Beam b, vec4 c) { return beamVisibilityClip(b, softShadowSetup(b), c); }

// V(x) in the medium.
float beamVisibilityVolume(Beam b, vec3 x) { return beamVisibilityClip(b, b.shadowViewProj * vec4(x, 1.0)); }

// The plane through x with normal n in shadow-map coordinates, as the rise of the map depth
// per unit of map u and v: a plane stays a plane under the projection, so the map depth over
// it is affine in (u, v), and two points beside x on it give the slope exactly. A lookup then
// compares each tap against the receiver's own plane where the tap lies, not against x's depth
// everywhere: on a surface slanted to the lens, half of a blocker search would otherwise find
// the surface itself nearer than x, count it as a blocker and pull the penumbra's estimate
// towards a hard edge, and no pyramid test could ever clear the point. 0 where the plane is
// seen edge-on (no slope to speak of in (u, v)).
vec2 receiverPlaneSlope(mat4 m, vec3 x, vec3 n, float r) {
  vec3 t1 = normalize(cross(n, abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
  vec3 t2 = cross(n, t1);
  vec4 c0 = m * vec4(x, 1.0), c1 = c0 + m * vec4(0.05 * r * t1, 0.0), c2 = c0 + m * vec4(0.05 * r * t2, 0.0);
  vec3 s0 = c0.xyz / c0.w, d1 = c1.xyz / c1.w - s0, d2 = c2.xyz / c2.w - s0;
  float det = d1.x * d2.y - d1.y * d2.x;
  // d1.xy g = d1.z and d2.xy g = d2.z (NDC and map units scale x, y and z alike), by Cramer.
  vec2 g = vec2(d1.z * d2.y - d1.y * d2.z, d1.x * d2.z - d1.z * d2.x) / det;
  return abs(det) > 1e-12 && c0.w > 0.0 && all(lessThan(abs(g), vec2(1e4))) ? g : vec2(0.0);
}

// V(x) at a surface point with normal n (facing the lens), r metres from it: 1 where the lens
// sees x, 0 in shadow.
float beamVisibility(Beam b, vec3 x, vec3 n, float r) {
  return visibilityAt(b, softShadowSetup(b), b.shadowViewProj * vec4(x, 1.0), receiverPlaneSlope(b.shadowViewProj, x, n, r),
                      SOFT_SURFACE_BLOCKER_TAPS, SOFT_SURFACE_FILTER_TAPS, 5);
}
