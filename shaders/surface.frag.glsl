// Surfaces lit by every beam and the sun, per docs/physics.md: two-sided Lambert with I_eff, V, cosine,
// exp(-sigma_t r) / r^2, plus ambient and emission, then attenuated by exp(-sigma_t T) to the eye.
// A full-screen pass over the attributes gbuffer.frag.glsl left at each pixel: each pixel is lit once.
#include "beams.glsl"
#include "camera.glsl"
#include "density.glsl"
#include "sun.glsl"

layout(location = HAZE_LOC_SURFACE_SIGMA_T) uniform float uSigmaT;
layout(location = HAZE_LOC_SURFACE_AMBIENT) uniform vec3 uAmbient;
layout(location = HAZE_LOC_SURFACE_BEAM_COUNT) uniform int uBeamCount;
layout(location = HAZE_LOC_SURFACE_TILE_COLUMNS) uniform int uTileColumns;  // 0: no tile masks, every beam is tried
layout(location = HAZE_LOC_SURFACE_MASK_WORDS) uniform int uMaskWords;      // 32-bit words per tile
layout(std430, binding = HAZE_SSBO_TILE_MASKS) readonly buffer TileMasks { uint tileMasks[]; };
layout(binding = HAZE_UNIT_GBUFFER) uniform usampler2D uAttributes;

vec3 fromOctahedral(vec2 p) {
  vec3 n = vec3(p, 1.0 - abs(p.x) - abs(p.y));
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
  return normalize(n);
}

layout(location = HAZE_FRAG_OUT) out vec4 outRadiance;

// Irradiance from one beam at this surface point (facing n): I_eff V cos exp(-sigma_t r) / r^2.
vec3 beamIrradiance(int i, vec3 vPosition, vec3 n) {
  Beam b = beams[i];
  // Most beams miss most pixels: test the cone before anything else.
  vec3 d = vPosition - b.lensPos.xyz;
  if (dot(d, b.zb.xyz) <= b.lensPos.w * length(d)) return vec3(0.0);
  vec3 wl;
  float r;
  vec3 I = beamIntensity(b, vPosition, wl, r);
  float cosine = dot(n, -wl);
  if (cosine <= 0.0 || I == vec3(0.0)) return vec3(0.0);
  // Shadow lookups from a point nudged off the surface, so that the PCF taps (up to a texel
  // and a half from the centre) do not compare the surface against its own depth a texel
  // away: at least 1.5 mm per metre from the lens, and on a slanted surface a texel and a half
  // of this beam's shadow map times the slant (a wide cutoff's frustum has texels ten times
  // the size of a spot's; 1.5 mm per metre left its faces mottled, a diagonal lattice).
  // 1 / tan(fov / 2) is the length of the shadow matrix's first row (a rotation times it).
  mat4 m = b.shadowViewProj;
  float texelPerM = 2.0 / (length(vec3(m[0][0], m[1][0], m[2][0])) * float(textureSize(uShadowMaps, 0).x));
  float slant = sqrt(max(1.0 - cosine * cosine, 0.0));
  float v = beamVisibility(b, vPosition + n * (max(0.0015, 1.5 * texelPerM * slant) * r), n, r);
  float path = r;
  if (DENSITY_ON) {  // the light's path through D (docs/physics.md, section 9)
    vec2 uv = vec2(dot(wl, b.xb.xyz), dot(wl, b.yb.xyz)) / dot(wl, b.zb.xyz) * b.xb.w * 0.5 + 0.5;
    path = lensPathTo(i, uv, r, b.lens.w);
  }
  return I * (v * cosine * exp(-uSigmaT * path) / (r * r));
}

void main() {
  // Soft shadows' tap pattern turned per pixel (interleaved gradient noise, Jimenez 2014).
  gShadowTurn = fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec2 size = vec2(textureSize(uSceneDepth, 0));
  vec2 uv = gl_FragCoord.xy / size;
  if (texelFetch(uSceneDepth, px, 0).r >= 1.0) discard;  // no surface: the background stays
  // The surface point from the depth: eye + view depth * the pixel centre's ray, as the
  // rasteriser interpolated it there (to the depth buffer's precision, 1e-7 of n f / (f - n)).
  vec3 vPosition = uEye + sceneViewDepth(uv) * eyeRay(uv * 2.0 - 1.0);
  vec3 toEye = uEye - vPosition;
  float T = length(toEye);
  uvec4 a = texelFetch(uAttributes, px, 0);
  vec3 n = fromOctahedral(unpackSnorm2x16(a.x));
  if (dot(n, toEye) < 0.0) n = -n;  // two-sided: the normal faces the eye
  vec2 ab = unpackHalf2x16(a.z);
  vec3 albedo = vec3(unpackHalf2x16(a.y), ab.x);
  vec3 emission = vec3(ab.y, unpackHalf2x16(a.w));

  vec3 irradiance = vec3(0.0);
  if (uTileColumns == 0) {
    for (int i = 0; i < uBeamCount; ++i) irradiance += beamIrradiance(i, vPosition, n);
  } else {
    ivec2 tile = ivec2(gl_FragCoord.xy) / HAZE_TILE_PX;
    int base = (tile.y * uTileColumns + tile.x) * uMaskWords;
    for (int w = 0; w < uMaskWords; ++w) {
      for (uint bits = tileMasks[base + w]; bits != 0u; bits &= bits - 1u)
        irradiance += beamIrradiance(w * 32 + findLSB(bits), vPosition, n);
    }
  }
  if (SUN_ON) irradiance += sunIrradiance(vPosition, n, uSigmaT);
  vec3 L = albedo / PI * irradiance + albedo * uAmbient + emission;
  outRadiance = vec4(L * exp(-uSigmaT * (DENSITY_ON ? eyePathTo(vPosition) : T)), 1.0);
}
