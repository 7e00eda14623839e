// The surfaces' attributes at each pixel, for surface.frag.glsl to light every pixel once. Lit in
// the venue's own pass, a pixel was shaded again for every triangle that touched its block: a CPU
// rasteriser (llvmpipe) runs the shader over a whole 4x4 block, masked, and a venue of 100k small
// triangles touches most blocks many times, each time with every beam of the tile.
#include "interface.h"

in vec3 vPosition;
in vec3 vNormal;
in vec2 vUv;

layout(location = HAZE_LOC_SURFACE_BASE_COLOR) uniform vec4 uBaseColor;
layout(location = HAZE_LOC_SURFACE_EMISSIVE) uniform vec3 uEmissive;
layout(location = HAZE_LOC_SURFACE_HAS_BASE_TEXTURE) uniform int uHasBaseTexture;
layout(location = HAZE_LOC_SURFACE_HAS_EMISSIVE_TEXTURE) uniform int uHasEmissiveTexture;
layout(binding = HAZE_UNIT_BASE_TEXTURE) uniform sampler2D uBaseTexture;
layout(binding = HAZE_UNIT_EMISSIVE_TEXTURE) uniform sampler2D uEmissiveTexture;

layout(location = HAZE_FRAG_OUT) out uvec4 outAttributes;

// A unit vector on the octahedron folded onto [-1, 1]^2 (Cigolle et al. 2014): 16 bits a
// component keep it within 1e-4 rad.
vec2 octahedral(vec3 n) {
  vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
  return n.z >= 0.0 ? p : (1.0 - abs(p.yx)) * vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
}

void main() {
  vec3 albedo = uBaseColor.rgb;
  if (uHasBaseTexture != 0) albedo *= texture(uBaseTexture, vUv).rgb;
  vec3 emission = uEmissive;
  if (uHasEmissiveTexture != 0) emission *= texture(uEmissiveTexture, vUv).rgb;
  emission = min(emission, vec3(65504.0));  // a half float's largest
  outAttributes = uvec4(packSnorm2x16(octahedral(normalize(vNormal))), packHalf2x16(albedo.rg),
                        packHalf2x16(vec2(albedo.b, emission.r)), packHalf2x16(emission.gb));
}
