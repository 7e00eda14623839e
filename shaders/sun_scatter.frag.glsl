// The sun's in-scattering along each pixel's eye ray (docs/rendering.md, "The sun"): a march
// over the ray's chord through the venue's box, up to the scene, in equal steps jittered per
// pixel and per frame, each sample V_sun (the shadow map) times both transmittances (through a
// density field: D(x), the eye's path map and the sun's, shaders/density.glsl and sun.glsl). The phase
// function is one value per ray (the sun's direction is the same everywhere). Added into the
// beams' scattering buffer, so it shares their accumulation and depth-aware upsample.
#include "camera.glsl"
#include "phase.glsl"
#include "density.glsl"
#include "sun.glsl"

in vec2 vUv;
layout(location = HAZE_LOC_SUN_MARCH) uniform vec4 uMarch;  // sigma_s, sigma_t, steps, frame jitter
layout(location = HAZE_FRAG_OUT) out vec4 outAdd;

// Interleaved gradient noise (Jimenez 2014), as planes.frag.glsl's.
float ign(vec2 p) { return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715)))); }

void main() {
  vec3 ray = eyeRay(vUv * 2.0 - 1.0);
  float len = length(ray);
  vec3 v = ray / len;
  // The march stops a texel of the shadow map short of the scene: the map's PCF tap a texel
  // around a sample just in front of a wall the sun never reaches reads texels of neighbouring
  // surfaces, a speckle of light on that wall.
  float mapWidthM = 2.0 / length(vec3(uSunViewProj[0][0], uSunViewProj[1][0], uSunViewProj[2][0]));
  float gapM = mapWidthM / float(textureSize(uSunShadow, 0).x);
  vec2 chord = sunBoxChord(uEye, v, sceneViewDepth(vUv) * len - gapM);
  if (!(chord.y > chord.x)) {
    outAdd = vec4(0.0);
    return;
  }
  int steps = max(int(uMarch.z), 1);
  float dt = (chord.y - chord.x) / float(steps);
  float xi = fract(ign(gl_FragCoord.xy) + uMarch.w);
  float sum = 0.0;
  for (int i = 0; i < steps; ++i) {
    float t = chord.x + (float(i) + xi) * dt;
    vec3 x = uEye + v * t;
    float vis = sunVisibilityVolume(x);
    if (vis <= 0.0) continue;
    if (!DENSITY_ON)
      sum += vis * exp(-uMarch.y * (sunPathInBox(x) + t));
    else  // sigma_s(x) = D(x) sigma_s, both paths integrals of D (docs/physics.md, section 9)
      sum += vis * densityAt(x) * exp(-uMarch.y * (sunPathTo(x) + eyePathTo(x)));
  }
  outAdd = vec4(uSunIlluminance * (uMarch.x * phaseFunction(-dot(uSunDirection, v)) * sum * dt), 0.0);
}
