// Display encoding of the radiometric image (physics.md, "Images"): exposure, then the ACES
// filmic fit of Narkowicz 2015 as the tone curve, then the sRGB transfer function.
in vec2 vUv;
layout(binding = 0) uniform sampler2D uRadiance;
layout(location = 0) uniform float uExposure;   // multiplies cd/m^2 before the curve
layout(location = 0) out vec4 outColor;

vec3 aces(vec3 x) {
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
vec3 srgbEncode(vec3 c) {
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
  vec3 L = texture(uRadiance, vUv).rgb;
  outColor = vec4(srgbEncode(aces(L * uExposure)), 1.0);
}
