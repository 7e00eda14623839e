// Virtual planes' in-scattering at this pixel, added into the scattering buffer, with the
// planes' depths jittered per pixel and per frame so few planes give noise, not slices.
// FUSED: one fragment walks every plane of the beam that its ray crosses inside the light cone
// (the planes clipped to the light volume per pixel). LATTICE: interpolated lattice values
// (the paper's method). Otherwise one fragment per plane instance (the paper's planes, sampled
// per pixel). See docs/rendering.md.
#include "cone.glsl"
#include "scatter.glsl"

flat in int vPlane;
#ifdef LATTICE
in vec3 vScatter;
in float vDepth;
#endif

layout(location = HAZE_FRAG_OUT) out vec4 outScatter;

// Interleaved gradient noise (Jimenez 2014): a cheap per-pixel offset with blue-ish spectrum.
float ign(vec2 p) { return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715)))); }

void main() {
  vec2 uv = gl_FragCoord.xy / uTargetSize;
  float zScene = sceneViewDepth(uv);
#ifdef LATTICE
  if (vDepth > zScene || vDepth <= uNearFar.x) discard;  // behind the first surface, or the eye
  outScatter = vec4(vScatter, 0.0);
#else
  vec3 v = eyeRay(uv * 2.0 - 1.0);
  float len = length(v);  // metres of ray per metre of view depth
  float xi = uJitter != 0 ? fract(ign(gl_FragCoord.xy) + uFrameJitter) : 0.5;
  float dz = uDepthRange.y;
  Beam b = beams[uBeam];
#ifdef FUSED
  float zMin = max(uDepthRange.x, uNearFar.x);
  float zMax = min(uDepthRange.x + dz * float(uPlanes), zScene);
  vec2 seg = coneInterval(uEye, v, b.lensPos.xyz, b.zb.xyz, b.lensPos.w * b.lensPos.w, zMin, zMax);
  if (seg.y <= seg.x) discard;
  // A ray that crosses the cone between few planes (a beam seen from the side) gets its chord
  // split into uMinSamples equal strata instead, one jittered sample in each.
  float zBase = uDepthRange.x;
  if ((seg.y - seg.x) < float(uMinSamples) * dz) {
    dz = (seg.y - seg.x) / float(uMinSamples);
    zBase = seg.x;
  }
  int k0 = int(ceil((seg.x - zBase) / dz - xi));
  int k1 = int(floor((seg.y - zBase) / dz - xi));
  vec3 L = vec3(0.0);
  BeamRay ray = beamRay(b, v, len);
  // Where the chord passes the lens closer than one step, 1/r^2 peaks within one step and
  // equal depth steps miss it (the lamp's own pixel came out black): there the chord is
  // walked in equal steps of the angle phi seen from the lens instead, as the reference does,
  // t = t_c + D tan(phi), dt = D / cos^2(phi) dphi, which follows the peak exactly.
  float tc = -dot(ray.d0, v) / len;                     // metres along the ray to the closest approach
  float D = max(length(ray.d0 + (tc / len) * v), 1e-6);  // its distance from the lens
  float t0 = seg.x * len, t1 = seg.y * len;
  float rMin = tc < t0 ? length(ray.d0 + seg.x * v) : tc > t1 ? length(ray.d0 + seg.y * v) : D;
  if (rMin < dz * len) {
    int n = max(k1 - k0 + 1, uMinSamples);
    float phi0 = atan(t0 - tc, D), phi1 = atan(t1 - tc, D);
    float dphi = (phi1 - phi0) / float(n);
    for (int k = 0; k < n; ++k) {
      float phi = phi0 + (float(k) + xi) * dphi;
      float c = cos(phi);
      L += scatterAt(b, ray, (tc + D * tan(phi)) / len) * (D / (c * c));
    }
    if (L == vec3(0.0)) discard;
    outScatter = vec4(L * dphi, 0.0);
    return;
  }
  for (int k = k0; k <= k1; ++k) L += scatterAt(b, ray, zBase + (float(k) + xi) * dz);
  if (L == vec3(0.0)) discard;
  outScatter = vec4(L * dz * len, 0.0);
#else
  float z = uDepthRange.x + (float(vPlane) + xi) * dz;
  if (z > zScene || z <= uNearFar.x) discard;  // behind the first surface, or the eye
  vec3 L = scatterSample(b, v, len, z);
  if (L == vec3(0.0)) discard;
  outScatter = vec4(L * dz * len, 0.0);
#endif
#endif
}
