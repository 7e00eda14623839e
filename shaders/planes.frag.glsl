// One virtual plane's in-scattering at this pixel, added into the scattering buffer:
// sigma_s p(a) V(x) I_eff(w_l) exp(-sigma_t r) / r^2 exp(-sigma_t t) dt (physics.md), with the
// plane's depth jittered per pixel and per frame so few planes give noise, not slices.
#include "beams.glsl"
#include "camera.glsl"
#include "phase.glsl"

flat in int vPlane;
layout(location = 1) uniform vec2 uDepthRange;   // zNear, dz
layout(location = 2) uniform int uBeam;
layout(location = 3) uniform float uSigmaS;
layout(location = 4) uniform float uSigmaT;
layout(location = 5) uniform vec2 uTargetSize;   // scattering buffer size in pixels
layout(location = 6) uniform float uFrameJitter; // in [0, 1), changes per accumulated frame
layout(location = 7) uniform int uJitter;        // 0: plane centres (no jitter)

layout(location = 0) out vec4 outScatter;

// Interleaved gradient noise (Jimenez 2014): a cheap per-pixel offset with blue-ish spectrum.
float ign(vec2 p) { return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715)))); }

void main() {
  vec2 uv = gl_FragCoord.xy / uTargetSize;
  vec3 v = eyeRay(uv * 2.0 - 1.0);
  float xi = uJitter != 0 ? fract(ign(gl_FragCoord.xy) + uFrameJitter) : 0.5;
  float z = uDepthRange.x + (float(vPlane) + xi) * uDepthRange.y;
  if (z > sceneViewDepth(uv) || z <= uNearFar.x) discard;  // behind the first surface, or the eye
  vec3 x = uEye + z * v;
  Beam b = beams[uBeam];
  vec3 wl;
  float r;
  vec3 I = beamIntensity(b, x, wl, r);
  if (I == vec3(0.0)) discard;
  float vis = beamVisibility(b, x);
  if (vis <= 0.0) discard;
  float len = length(v);  // metres of ray per metre of view depth
  float t = z * len;
  vec3 wOut = -v / len;
  float dt = uDepthRange.y * len;
  vec3 L = uSigmaS * phaseFunction(dot(wl, wOut)) * vis * I * exp(-uSigmaT * (r + t)) / (r * r) * dt;
  outScatter = vec4(L, 0.0);
}
