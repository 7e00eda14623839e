// One sample of docs/physics.md's in-scattering integrand for a beam at view depth z on the eye ray
// v (with dot(v, forward) = 1, len = |v|): sigma_s p(a) V(x) I_eff exp(-sigma_t (r + t)) / r^2.
#include "beams.glsl"
#include "camera.glsl"
#include "density.glsl"
#include "phase.glsl"
#include "interface.h"

layout(location = HAZE_LOC_SCATTER_DEPTH_RANGE) uniform vec2 uDepthRange;    // zNear, dz
layout(location = HAZE_LOC_SCATTER_BEAM) uniform int uBeam;
layout(location = HAZE_LOC_SCATTER_SIGMA_S) uniform float uSigmaS;
layout(location = HAZE_LOC_SCATTER_SIGMA_T) uniform float uSigmaT;
layout(location = HAZE_LOC_SCATTER_TARGET_SIZE) uniform vec2 uTargetSize;    // scattering buffer size in pixels
layout(location = HAZE_LOC_SCATTER_FRAME_JITTER) uniform float uFrameJitter; // in [0, 1), per accumulated frame
layout(location = HAZE_LOC_SCATTER_JITTER) uniform int uJitter;              // 0: plane centres (no jitter)
layout(location = HAZE_LOC_SCATTER_PLANES) uniform int uPlanes;
layout(location = HAZE_LOC_SCATTER_MIN_SAMPLES) uniform int uMinSamples;     // per ray chord through the cone
layout(location = HAZE_LOC_SCATTER_LATTICE) uniform ivec2 uLattice;          // LATTICE: cells across the footprint

vec3 scatterSample(Beam b, vec3 v, float len, float z) {
  vec3 x = uEye + z * v;
  vec3 wl;
  float r;
  vec3 I = beamIntensity(b, x, wl, r);
  if (I == vec3(0.0)) return vec3(0.0);
  float vis = beamVisibilityVolume(b, x);
  float t = z * len;
  if (!DENSITY_ON)
    return uSigmaS * phaseFunction(dot(wl, -v / len)) * vis * I * exp(-uSigmaT * (r + t)) / (r * r);
  // sigma_s(x) = D(x) sigma_s, both transmittances over the paths through D (docs/physics.md, 9).
  float cz = dot(wl, b.zb.xyz);
  vec2 uv = vec2(dot(wl, b.xb.xyz), dot(wl, b.yb.xyz)) / cz * b.xb.w * 0.5 + 0.5;
  float path = lensPathTo(uBeam, uv, r, b.lens.w) + eyePathTo(x);
  return uSigmaS * densityAt(x) * phaseFunction(dot(wl, -v / len)) * vis * I * exp(-uSigmaT * path) / (r * r);
}

// The same integrand along one eye ray, with what is linear in the view depth z set up once per
// ray: x(z) - lens, the light-map projections and the shadow map's clip coordinates are all
// a + z * b, so a sample costs a few multiply-adds, one light-map and one shadow-map lookup.
struct BeamRay {
  vec3 d0, d1;   // x - lens
  vec3 p0, p1;   // (x - lens) . (xb, yb, zb)
  vec4 c0, c1;   // shadow clip coordinates
  float q0, q1;  // (x - lens) . (-v / len)
  float len;
};

BeamRay beamRay(Beam b, vec3 v, float len) {
  BeamRay s;
  s.d0 = uEye - b.lensPos.xyz;
  s.d1 = v;
  mat3 frame = transpose(mat3(b.xb.xyz, b.yb.xyz, b.zb.xyz));
  s.p0 = frame * s.d0;
  s.p1 = frame * v;
  s.c0 = b.shadowViewProj * vec4(uEye, 1.0);
  s.c1 = b.shadowViewProj * vec4(v, 0.0);
  s.q0 = -dot(s.d0, v) / len;
  s.q1 = -dot(v, v) / len;
  s.len = len;
  return s;
}

// vRange: the least and largest V the walk has seen so far (the hard shadows' second pass,
// planes.frag.glsl). shadowed false: the caller knows V = 1 (a chord no lookup can find a
// blocker for), and the lookups are left out.
vec3 scatterAt(Beam b, BeamRay s, SoftShadowSetup ss, bool shadowed, float z, inout vec2 vRange) {
  vec3 d = s.d0 + z * s.d1;
  float r2 = max(dot(d, d), 1e-12);
  float r = sqrt(r2);
  vec3 p = s.p0 + z * s.p1;
  if (p.z <= b.lensPos.w * r) return vec3(0.0);  // outside the cone
  vec2 uv = p.xy / p.z * b.xb.w * 0.5 + 0.5;
  float cd = texture(uLightMaps, vec3(uv, b.yb.w)).r;
  float vis = shadowed ? beamVisibilityClip(b, ss, s.c0 + z * s.c1) : 1.0;
  vRange = vec2(min(vRange.x, vis), max(vRange.y, vis));
  float cosA = (s.q0 + z * s.q1) / r;
  if (!DENSITY_ON)
    return uSigmaS * phaseFunction(cosA) * vis * cd * b.color.rgb * exp(-uSigmaT * (r + z * s.len)) / r2;
  // sigma_s(x) = D(x) sigma_s, both transmittances over the paths through D (docs/physics.md, 9).
  vec3 x = b.lensPos.xyz + d;
  float path = lensPathTo(uBeam, uv, r, b.lens.w) + eyePathTo(x);
  return uSigmaS * densityAt(x) * phaseFunction(cosA) * vis * cd * b.color.rgb * exp(-uSigmaT * path) / r2;
}
