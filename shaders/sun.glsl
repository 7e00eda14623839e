// The sun as the lighting shaders see it (docs/physics.md, "The sun"): a direction, c * E, an
// orthographic shadow map over the venue's bounding box, and the box itself, which is the
// medium the sun's light crosses (T_sun) and scatters in. Include density.glsl before this.
#include "interface.h"

layout(location = HAZE_LOC_SUN_ON) uniform int uSunOn;
#if defined(STATIC_FEATURES) && !defined(SUN)
#define SUN_ON false  // compiled out (shaders/interface.h, "Static features")
#else
#define SUN_ON (uSunOn != 0)
#endif
layout(location = HAZE_LOC_SUN_DIRECTION) uniform vec3 uSunDirection;
layout(location = HAZE_LOC_SUN_ILLUMINANCE) uniform vec3 uSunIlluminance;
layout(location = HAZE_LOC_SUN_VIEW_PROJ) uniform mat4 uSunViewProj;
layout(location = HAZE_LOC_SUN_BOX_MIN) uniform vec3 uSunBoxMin;
layout(location = HAZE_LOC_SUN_BOX_MAX) uniform vec3 uSunBoxMax;
layout(binding = HAZE_UNIT_SUN_SHADOW) uniform sampler2DShadow uSunShadow;
// With a density field: at the centres of the field's cells, the integral of D from there
// towards the sun to the box's edge (renderer/sun_pass.cpp), trilinear like D itself.
layout(binding = HAZE_UNIT_SUN_PATH) uniform sampler3D uSunPath;

// The length of the ray from x towards the sun inside the box; 0 from outside it.
float sunPathInBox(vec3 x) {
  if (any(lessThan(x, uSunBoxMin)) || any(greaterThan(x, uSunBoxMax))) return 0.0;
  vec3 u = -uSunDirection;
  vec3 safe = mix(vec3(1e-12), u, greaterThan(abs(u), vec3(1e-12)));
  vec3 exitT = max((uSunBoxMax - x) / safe, (uSunBoxMin - x) / safe);
  return max(min(exitT.x, min(exitT.y, exitT.z)), 0.0);
}

// The sun's optical path to x in metres of nominal medium: its length in the box, or through a
// density field the integral of D along it.
float sunPathTo(vec3 x) {
  if (!DENSITY_ON) return sunPathInBox(x);
  if (any(lessThan(x, uSunBoxMin)) || any(greaterThan(x, uSunBoxMax))) return 0.0;
  return texture(uSunPath, (x - uDensityMin) * uDensityInvSize).r;
}

// The eye ray's chord [t0, t1] through the box, within [0, tMax]; t1 <= t0 when it misses.
vec2 sunBoxChord(vec3 e, vec3 v, float tMax) {
  vec3 safe = mix(vec3(1e-12), v, greaterThan(abs(v), vec3(1e-12)));
  vec3 ta = (uSunBoxMin - e) / safe, tb = (uSunBoxMax - e) / safe;
  vec3 lo = min(ta, tb), hi = max(ta, tb);
  return vec2(max(0.0, max(lo.x, max(lo.y, lo.z))), min(tMax, min(hi.x, min(hi.y, hi.z))));
}

// Where x falls in the map, its (u, v) clamped half a texel inside the map's edges, which are
// the venue box's: a wall on the box's face that the sun only grazes covers no texel of its
// own, and the empty texels beyond it would light a slab of air along it.
vec3 sunMapCoord(vec3 x) {
  vec3 s = (uSunViewProj * vec4(x, 1.0)).xyz * 0.5 + 0.5;
  vec2 halfTexel = 0.5 / vec2(textureSize(uSunShadow, 0));
  return vec3(clamp(s.xy, halfTexel, 1.0 - halfTexel), s.z);
}

// V_sun at a point of the medium: one hardware 2x2 PCF tap, the point taken a texel and a half
// farther from the sun: air just behind a wall that the sun meets at a slant otherwise reads
// the wall's depth a texel away as in front of it (a speckle of light inside the wall).
float sunVisibilityVolume(vec3 x) {
  vec3 s = sunMapCoord(x);
  if (s.z < 0.0 || s.z > 1.0) return 1.0;
  float mapWidthM = 2.0 / length(vec3(uSunViewProj[0][0], uSunViewProj[1][0], uSunViewProj[2][0]));
  float depthPerM = 0.5 * length(vec3(uSunViewProj[0][2], uSunViewProj[1][2], uSunViewProj[2][2]));
  float bias = 1.5 * mapWidthM / float(textureSize(uSunShadow, 0).x) * depthPerM;
  return texture(uSunShadow, vec3(s.xy, s.z + bias));
}

// V_sun at a surface point: the 2x2 tap and four around it, as the beams' surfaces have.
float sunVisibility(vec3 x) {
  vec3 s = sunMapCoord(x);
  if (s.z < 0.0 || s.z > 1.0) return 1.0;
  vec2 texel = 1.0 / vec2(textureSize(uSunShadow, 0));
  float v = texture(uSunShadow, s) * 0.5;
  v += texture(uSunShadow, vec3(s.xy + vec2(0.5, 0.5) * texel, s.z)) * 0.125;
  v += texture(uSunShadow, vec3(s.xy + vec2(-0.5, 0.5) * texel, s.z)) * 0.125;
  v += texture(uSunShadow, vec3(s.xy + vec2(0.5, -0.5) * texel, s.z)) * 0.125;
  v += texture(uSunShadow, vec3(s.xy + vec2(-0.5, -0.5) * texel, s.z)) * 0.125;
  return v;
}

// c E max(0, n . -d) V_sun T_sun at surface point x facing n (unit); sigmaT the extinction.
vec3 sunIrradiance(vec3 x, vec3 n, float sigmaT) {
  float cosine = dot(n, -uSunDirection);
  if (cosine <= 0.0) return vec3(0.0);
  // Off the surface by a texel and a half of the map times the slant (and 2 mm), so the PCF
  // taps do not compare the surface with itself a texel away. The first row of an orthographic
  // matrix has length 2 / (the map's width in metres).
  float mapWidthM = 2.0 / length(vec3(uSunViewProj[0][0], uSunViewProj[1][0], uSunViewProj[2][0]));
  float texelM = mapWidthM / float(textureSize(uSunShadow, 0).x);
  float slant = sqrt(max(1.0 - cosine * cosine, 0.0));
  float v = sunVisibility(x + n * max(0.002, 1.5 * texelM * slant / max(cosine, 0.2)));
  // A surface lies in the venue's box (the box is its bounds), but the point the depth buffer
  // gives a floor on the box's face may be a micrometre outside it, where the path would be 0.
  return uSunIlluminance * (cosine * v * exp(-sigmaT * sunPathTo(clamp(x, uSunBoxMin, uSunBoxMax))));
}
