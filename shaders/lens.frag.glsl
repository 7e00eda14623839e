// A lens disc seen by the eye: from the front a disc of uniform luminance whose intensity
// towards the eye is I_eff(w_e), L_lens = I_eff(w_e) / (pi r_lens^2 cos theta_e), attenuated
// to the eye like a surface; from behind black. Either way it is opaque (it writes depth), so
// the beam pass stops the eye ray's in-scattering there (docs/physics.md, "The lens").
#include "beams.glsl"
#include "camera.glsl"
#include "density.glsl"

layout(location = HAZE_LOC_LENS_SIGMA_T) uniform float uSigmaT;

in vec2 vDisc;
in vec3 vPosition;
flat in int vBeam;

layout(location = HAZE_FRAG_OUT) out vec4 outRadiance;

void main() {
  if (dot(vDisc, vDisc) > 1.0) discard;
  Beam b = beams[vBeam];
  vec3 L = vec3(0.0);
  vec3 toEye = uEye - b.lensPos.xyz;
  float cosE = dot(normalize(toEye), b.zb.xyz);
  if (cosE > 0.0) {
    vec3 wl;
    float r;
    vec3 I = beamIntensity(b, uEye, wl, r);
    float path = DENSITY_ON ? eyePathTo(vPosition) : length(vPosition - uEye);
    L = I * b.lens.y / cosE * exp(-uSigmaT * path);
  }
  outRadiance = vec4(L, 1.0);
}
