// One particle of visible dust lit by one beam (docs/rendering.md, "Particles"; docs/physics.md,
// "Particles"). Texel 2i of the buffer is (position, cross-section), texel 2i + 1 (beam, ...).
// The particle scatters towards the eye J = G C p(a) V I_eff / r^2 exp(-sigma_t path_lens); its
// flux at the eye, J exp(-sigma_t path_eye) / d^2, is spread over a small kernel of pixels.
#include "beams.glsl"
#include "camera.glsl"
#include "phase.glsl"
#include "density.glsl"

layout(location = HAZE_LOC_PARTICLES_VIEW_PROJ) uniform mat4 uViewProj;
layout(location = HAZE_LOC_PARTICLES_SIGMA_T) uniform float uSigmaT;
layout(location = HAZE_LOC_PARTICLES_SPRITE) uniform vec4 uSprite;
layout(binding = HAZE_UNIT_PARTICLES) uniform samplerBuffer uParticles;

flat out vec3 vPeak;  // radiance at the kernel's centre

void main() {
  vec4 a = texelFetch(uParticles, 2 * gl_VertexID);
  vec4 t = texelFetch(uParticles, 2 * gl_VertexID + 1);
  Beam b = beams[int(t.x)];
  vec3 x = a.xyz;
  vec3 wl;
  float r;
  vec3 I = beamIntensity(b, x, wl, r);
  vec3 peak = vec3(0.0);
  if (max(I.r, max(I.g, I.b)) > 0.0) {
    float V = beamVisibilityVolume(b, x);
    vec3 toEye = uEye - x;
    float d = max(length(toEye), 1e-4);
    vec3 we = toEye / d;
    float lensPath = r, eyePath = d;
    if (DENSITY_ON) {
      float cz = dot(wl, b.zb.xyz);
      vec2 uv = vec2(dot(wl, b.xb.xyz), dot(wl, b.yb.xyz)) / cz * b.xb.w * 0.5 + 0.5;
      lensPath = lensPathTo(int(t.x), uv, r, b.lens.w);
      eyePath = eyePathTo(x);
    }
    vec3 J = uSprite.z * a.w * phaseFunction(dot(wl, we)) * V * I / (r * r) * exp(-uSigmaT * lensPath);
    float cosView = max(dot(-we, uForward), 1e-3);
    // A pixel's solid angle falls off as cos^3 away from the axis; the kernel's weights sum to 1.
    float perPixel = uSprite.y / (cosView * cosView * cosView);
    float R = uSprite.x;
    peak = J * exp(-uSigmaT * eyePath) / (d * d) * perPixel * 3.0 / (PI * R * R);
  }
  vPeak = peak;
  gl_PointSize = 2.0 * uSprite.x;
  // A dark particle is moved outside the clip volume, so it is not rasterised at all.
  gl_Position = max(peak.r, max(peak.g, peak.b)) > 0.0 ? uViewProj * vec4(x, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
}
