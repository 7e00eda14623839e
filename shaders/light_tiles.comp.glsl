// Tiled light culling (as in Forward+ renderers): for each 4x4-pixel (HAZE_TILE_PX) tile of the screen, a bit
// mask of the beams whose light cone can reach a surface seen in that tile, from the tile's depth
// bounds in the camera's depth. The surface pass then loops over those beams only: a fragment
// shader on a CPU rasteriser (llvmpipe) pays for every iteration of its light loop, however
// little an iteration does, so testing every beam at every pixel cost more than the lighting.
#include "beams.glsl"
#include "camera.glsl"

// One invocation per tile (no barriers or shared memory: on a CPU rasteriser those cost far
// more than reading the tile's depths in a loop).
layout(local_size_x = HAZE_TILE_GROUP_X, local_size_y = 1) in;
layout(std430, binding = HAZE_SSBO_TILE_MASKS) writeonly buffer TileMasks { uint tileMasks[]; };
layout(location = HAZE_LOC_TILES_TARGET_SIZE) uniform ivec2 uTargetSize;
layout(location = HAZE_LOC_TILES_BEAM_COUNT) uniform int uBeamCount;
layout(location = HAZE_LOC_TILES_MASK_WORDS) uniform int uMaskWords;
layout(location = HAZE_LOC_TILES_GRID) uniform ivec2 uTiles;  // columns, rows

float viewDepth(float d) {
  float n = uNearFar.x, f = uNearFar.y;
  return 2.0 * n * f / (f + n - (2.0 * d - 1.0) * (f - n));
}

// Whether a sphere reaches into a beam's cone (the test of Wronski, "Cull that cone", 2016):
// the sphere's centre lies within its radius of the cone's surface, or inside the cone.
bool sphereMeetsCone(vec3 centre, float radius, Beam b) {
  vec3 v = centre - b.lensPos.xyz;
  float along = dot(v, b.zb.xyz);
  float perp = sqrt(max(dot(v, v) - along * along, 0.0));
  float cosA = b.lensPos.w, sinA = sqrt(max(1.0 - cosA * cosA, 0.0));
  return along > -radius && cosA * perp - sinA * along <= radius;
}

void main() {
  ivec2 tileXY = ivec2(gl_GlobalInvocationID.xy);
  if (tileXY.x >= uTiles.x || tileXY.y >= uTiles.y) return;
  ivec2 p0 = tileXY * HAZE_TILE_PX, p1 = min(p0 + HAZE_TILE_PX, uTargetSize);
  float dMin = 1.0, dMax = 0.0;
  for (int y = p0.y; y < p1.y; ++y)
    for (int x = p0.x; x < p1.x; ++x) {
      float d = texelFetch(uSceneDepth, ivec2(x, y), 0).r;
      if (d < 1.0) {  // 1: no surface, nothing to light
        dMin = min(dMin, d);
        dMax = max(dMax, d);
      }
    }
  bool empty = dMin >= 1.0;
  float zMin = viewDepth(dMin), zMax = viewDepth(max(dMax, dMin));
  // The tile's frustum between its depth bounds, in a sphere (padded for rounding).
  vec2 ndc0 = vec2(p0) / vec2(uTargetSize) * 2.0 - 1.0;
  vec2 ndc1 = vec2(p1) / vec2(uTargetSize) * 2.0 - 1.0;
  vec3 centre = uEye + 0.5 * (zMin + zMax) * eyeRay(0.5 * (ndc0 + ndc1));
  float radius = 0.0;
  for (int c = 0; c < 8; ++c) {
    vec2 ndc = vec2((c & 1) != 0 ? ndc1.x : ndc0.x, (c & 2) != 0 ? ndc1.y : ndc0.y);
    vec3 x = uEye + ((c & 4) != 0 ? zMax : zMin) * eyeRay(ndc);
    radius = max(radius, distance(x, centre));
  }
  radius = radius * 1.01 + 1e-3;
  int tile = tileXY.y * uTiles.x + tileXY.x;
  for (int w = 0; w < uMaskWords; ++w) {
    uint bits = 0u;
    for (int k = 0; k < 32 && !empty; ++k) {
      int i = w * 32 + k;
      if (i >= uBeamCount) break;
      if (beams[i].color.rgb != vec3(0.0) && sphereMeetsCone(centre, radius, beams[i])) bits |= 1u << uint(k);
    }
    tileMasks[tile * uMaskWords + w] = bits;
  }
}
