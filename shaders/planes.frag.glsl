// Virtual planes' in-scattering at this pixel, added into the scattering buffer:
// sigma_s p(a) V(x) I_eff(w_l) exp(-sigma_t r) / r^2 exp(-sigma_t t) dt (physics.md), with the
// planes' depths jittered per pixel and per frame so few planes give noise, not slices.
// FUSED: one fragment walks every plane of the beam that its ray crosses inside the light cone
// (the planes clipped to the light volume per pixel); otherwise one fragment per plane instance
// (the paper's literal form, kept for the accuracy study).
#include "beams.glsl"
#include "camera.glsl"
#include "cone.glsl"
#include "phase.glsl"

flat in int vPlane;
layout(location = 1) uniform vec2 uDepthRange;   // zNear, dz
layout(location = 2) uniform int uBeam;
layout(location = 3) uniform float uSigmaS;
layout(location = 4) uniform float uSigmaT;
layout(location = 5) uniform vec2 uTargetSize;   // scattering buffer size in pixels
layout(location = 6) uniform float uFrameJitter; // in [0, 1), changes per accumulated frame
layout(location = 7) uniform int uJitter;        // 0: plane centres (no jitter)
layout(location = 8) uniform int uPlanes;
layout(location = 9) uniform int uMinSamples;    // per ray chord through the cone

layout(location = 0) out vec4 outScatter;

// Interleaved gradient noise (Jimenez 2014): a cheap per-pixel offset with blue-ish spectrum.
float ign(vec2 p) { return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715)))); }

vec3 sampleAt(Beam b, vec3 v, float len, float z) {
  vec3 x = uEye + z * v;
  vec3 wl;
  float r;
  vec3 I = beamIntensity(b, x, wl, r);
  if (I == vec3(0.0)) return vec3(0.0);
  float vis = beamVisibilityVolume(b, x);
  float t = z * len;
  return uSigmaS * phaseFunction(dot(wl, -v / len)) * vis * I * exp(-uSigmaT * (r + t)) / (r * r);
}

void main() {
  vec2 uv = gl_FragCoord.xy / uTargetSize;
  vec3 v = eyeRay(uv * 2.0 - 1.0);
  float len = length(v);  // metres of ray per metre of view depth
  float xi = uJitter != 0 ? fract(ign(gl_FragCoord.xy) + uFrameJitter) : 0.5;
  float zScene = sceneViewDepth(uv);
  float dz = uDepthRange.y;
  Beam b = beams[uBeam];
#ifdef FUSED
  float zMin = max(uDepthRange.x, uNearFar.x);
  float zMax = min(uDepthRange.x + dz * float(uPlanes), zScene);
  vec2 seg = coneInterval(uEye, v, b.lensPos.xyz, b.zb.xyz, b.lensPos.w * b.lensPos.w, zMin, zMax);
  if (seg.y <= seg.x) discard;
  // A ray that crosses the cone between few planes (a beam seen from the side) gets the plane
  // lattice refined by halving, dz / 2^k, until at least uMinSamples planes fall on its chord.
  float crossings = (seg.y - seg.x) / dz;
  if (crossings < float(uMinSamples)) {
    int k = min(int(ceil(log2(float(uMinSamples) / max(crossings, 1e-3)))), 8);
    dz = dz / float(1 << k);
  }
  int k0 = int(ceil((seg.x - uDepthRange.x) / dz - xi));
  int k1 = int(floor((seg.y - uDepthRange.x) / dz - xi));
  vec3 L = vec3(0.0);
  for (int k = k0; k <= k1; ++k) L += sampleAt(b, v, len, uDepthRange.x + (float(k) + xi) * dz);
  if (L == vec3(0.0)) discard;
  outScatter = vec4(L * dz * len, 0.0);
#else
  float z = uDepthRange.x + (float(vPlane) + xi) * dz;
  if (z > zScene || z <= uNearFar.x) discard;  // behind the first surface, or the eye
  vec3 L = sampleAt(b, v, len, z);
  if (L == vec3(0.0)) discard;
  outScatter = vec4(L * dz * len, 0.0);
#endif
}
