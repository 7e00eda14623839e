// One sample of physics.md's in-scattering integrand for a beam at view depth z on the eye ray
// v (with dot(v, forward) = 1, len = |v|): sigma_s p(a) V(x) I_eff exp(-sigma_t (r + t)) / r^2.
#include "beams.glsl"
#include "camera.glsl"
#include "phase.glsl"

layout(location = 1) uniform vec2 uDepthRange;   // zNear, dz
layout(location = 2) uniform int uBeam;
layout(location = 3) uniform float uSigmaS;
layout(location = 4) uniform float uSigmaT;
layout(location = 5) uniform vec2 uTargetSize;   // scattering buffer size in pixels
layout(location = 6) uniform float uFrameJitter; // in [0, 1), changes per accumulated frame
layout(location = 7) uniform int uJitter;        // 0: plane centres (no jitter)
layout(location = 8) uniform int uPlanes;
layout(location = 9) uniform int uMinSamples;    // per ray chord through the cone
layout(location = 10) uniform ivec2 uLattice;    // LATTICE: lattice cells across the footprint

vec3 scatterSample(Beam b, vec3 v, float len, float z) {
  vec3 x = uEye + z * v;
  vec3 wl;
  float r;
  vec3 I = beamIntensity(b, x, wl, r);
  if (I == vec3(0.0)) return vec3(0.0);
  float vis = beamVisibilityVolume(b, x);
  float t = z * len;
  return uSigmaS * phaseFunction(dot(wl, -v / len)) * vis * I * exp(-uSigmaT * (r + t)) / (r * r);
}
