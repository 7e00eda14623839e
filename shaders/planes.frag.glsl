// Virtual planes' in-scattering at this pixel, added into the scattering buffer, with the
// planes' depths jittered per pixel and per frame so few planes give noise, not slices.
// FUSED: one fragment walks every plane of the beam that its ray crosses inside the light cone
// (the planes clipped to the light volume per pixel). LATTICE: interpolated lattice values
// (the paper's method). Otherwise one fragment per plane instance (the paper's planes, sampled
// per pixel). See docs/rendering.md.
#include "cone.glsl"
#include "scatter.glsl"

#ifdef EARLY_STENCIL
// The refinement's pass (docs/rendering.md, "Refinement"): the stencil keeps the marked pixels,
// and tested before shading it saves the others' walks (the shader writes no depth or stencil).
layout(early_fragment_tests) in;
#endif

flat in int vPlane;
#ifdef LATTICE
in vec3 vScatter;
in float vDepth;
#endif

layout(location = HAZE_FRAG_OUT) out vec4 outScatter;

// Interleaved gradient noise (Jimenez 2014): a cheap per-pixel offset with blue-ish spectrum.
float ign(vec2 p) { return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715)))); }

// Whether no shadow lookup along the chord [seg.x, seg.y] can find a blocker: the chord's
// shadow-map image is the segment between its ends' (a projective map keeps lines), its window
// depth is monotone along it (c.z / c.w of a linear c), and a soft lookup's blocker search
// reaches 2 k / w around its point, widest at the chord's nearer end. So one pyramid texel
// over the box of both ends grown by that reach, against the farther end's depth, answers for
// every sample at once, and where it says lit each sample's own lookup would give exactly 1.
bool chordSurelyLit(Beam b, BeamRay ray, SoftShadowSetup ss, vec2 seg) {
  vec4 ca = ray.c0 + seg.x * ray.c1, cb = ray.c0 + seg.y * ray.c1;
  if (ca.w <= 0.0 || cb.w <= 0.0) return false;
  vec3 sa = ca.xyz / ca.w * 0.5 + 0.5, sb = cb.xyz / cb.w * 0.5 + 0.5;
  float reach = SOFT_SHADOWS_ON && b.lens.x > 0.0 ? 2.0 * ss.k / min(ca.w, cb.w) : 0.0;
  return surelyLitBox(b, min(sa.xy, sb.xy) - reach, max(sa.xy, sb.xy) + reach, max(sa.z, sb.z));
}

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
  gShadowTurn = fract(ign(gl_FragCoord.yx) + uFrameJitter);  // the soft shadows' taps (beams.glsl)
  float dz = uDepthRange.y;
  Beam b = beams[uBeam];
#ifdef FUSED
  float zMin = max(uDepthRange.x, uNearFar.x);
  float zMax = min(uDepthRange.x + dz * float(uPlanes), zScene);
  vec2 seg = coneInterval(uEye, v, b.lensPos.xyz, b.zb.xyz, b.lensPos.w * b.lensPos.w, zMin, zMax);
  if (seg.y <= seg.x) discard;
  // Where the samples go (docs/rendering.md, "Where the samples go"): the chord is walked in
  // equal steps of the angle phi seen from the lens, t = t_c + D tan(phi), dt = D / cos^2(phi)
  // dphi, so 1/r^2 (the integrand's fastest change, at the closest approach) is followed
  // exactly however narrow the beam and however close the eye; a chord that passes far from
  // the lens gets nearly equal depth steps. The planes set how many samples a chord gets: as
  // many as planes it crosses, at least uMinSamples. A beam whose light sits in a core much
  // narrower than its cutoff cone (a flood's 10 degrees inside light out to 80) has the core's
  // part of the chord walked apart, with the full count, and the dim rest with a quarter.
  BeamRay ray = beamRay(b, v, len);
  float tc = -dot(ray.d0, v) / len;                     // metres along the ray to the closest approach
  float D = max(length(ray.d0 + (tc / len) * v), 1e-6);  // its distance from the lens
  vec2 pieces[3];
  int nPieces = 0;
  vec2 core = b.lens.z > b.lensPos.w * b.lensPos.w
                  ? coneInterval(uEye, v, b.lensPos.xyz, b.zb.xyz, b.lens.z, seg.x, seg.y)
                  : seg;
  if (core.y <= core.x) {
    pieces[nPieces++] = seg;
  } else {
    if (core.x > seg.x) pieces[nPieces++] = vec2(seg.x, core.x);
    pieces[nPieces++] = core;
    if (seg.y > core.y) pieces[nPieces++] = vec2(core.y, seg.y);
  }
  bool hasCore = core.y > core.x;
  SoftShadowSetup ss = softShadowSetup(b);  // once per pixel, not per sample
  vec3 L = vec3(0.0);
  for (int p = 0; p < nPieces; ++p) {
    vec2 piece = pieces[p];
    bool inCore = !hasCore || piece == core;  // a chord that misses the core sees only the rest
    int minN = inCore ? uMinSamples : max(uMinSamples / 4, 2);
    // As many as the planes the piece spans (not a count that depends on the jitter: that
    // biases the strata).
    int n = max(int(round((piece.y - piece.x) / dz)), minN);
    // tan(phi) at the piece's ends is (t - t_c) / D; the angle between them is one arctangent
    // of the tangents' difference (atan2 keeps it right past 90 degrees), and tan(phi) goes from
    // one step to the next by the addition theorem (a division instead of a tan per sample:
    // the walk costs what equal depth steps cost).
    float T0 = (piece.x * len - tc) / D, T1 = (piece.y * len - tc) / D;
    float dphi = atan(T1 - T0, 1.0 + T0 * T1) / float(n);
    float tau = tan(dphi), tx = tan(xi * dphi);
    float T = (T0 + tx) / (1.0 - T0 * tx);
    vec3 Lp = vec3(0.0);
    // A hard shadow (a point lens) is a step in V along the chord, which one set of strata
    // places only to a stratum: a chord whose samples saw V change is walked again with the
    // strata moved by half their width, and the two walks averaged (2n strata). One loop whose
    // count grows, not a second loop: the sample is inlined once, and a block of pixels that
    // sees no shadow edge stops at n (llvmpipe runs a branch's both sides, a loop only as long
    // as one of its pixels needs). Soft shadows are a ramp that the strata integrate already
    // (docs/rendering.md, "Accuracy").
    bool hard = !SOFT_SHADOWS_ON || b.lens.x <= 0.0;
    vec2 vRange = vec2(1.0, 0.0);
    // A chord that no shadow lookup can find a blocker for is walked without them (V = 1), in
    // a loop of its own: the other loop's count is then 0, so a block of pixels whose chords
    // are all lit never runs the lookups (the pyramid's texel alone cost as much as the rest
    // of a sample).
    bool lit = chordSurelyLit(b, ray, ss, piece);
    for (int k = 0; k < (lit ? n : 0); ++k) {
      Lp += scatterAt(b, ray, ss, false, (tc + D * T) / len, vRange) * (1.0 + T * T);
      T = (T + tau) / (1.0 - T * tau);
    }
    int nAll = lit ? 0 : n;
    // Where the second walk starts (its strata moved by half), worked out before the loop: in
    // it, the branch's body would be run for every sample.
    float tx2 = tan(fract(xi + 0.5) * dphi);
    float T2 = (T0 + tx2) / (1.0 - T0 * tx2);
    for (int k = 0; k < nAll; ++k) {
      Lp += scatterAt(b, ray, ss, true, (tc + D * T) / len, vRange) * (1.0 + T * T);
      T = (T + tau) / (1.0 - T * tau);
      if (k == n - 1 && hard && vRange.y - vRange.x > 0.5) {
        nAll = 2 * n;
        T = T2;
      }
    }
    L += Lp * (D * dphi * float(n) / float(max(nAll, n)));
  }
  if (L == vec3(0.0)) discard;
  outScatter = vec4(L, 0.0);
#else
  float z = uDepthRange.x + (float(vPlane) + xi) * dz;
  if (z > zScene || z <= uNearFar.x) discard;  // behind the first surface, or the eye
  vec3 L = scatterSample(b, v, len, z);
  if (L == vec3(0.0)) discard;
  outScatter = vec4(L * dz * len, 0.0);
#endif
#endif
}
