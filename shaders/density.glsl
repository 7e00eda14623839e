// The density field D(x) and the optical paths through it (docs/physics.md, section 9;
// docs/rendering.md, "Density"). Paths are integrals of D in metres (an optical depth is
// sigma_t times one); without DENSITY_ON the medium is uniform: D = 1 and a path is its
// length, with no lookups. The two path maps are made on the CPU (renderer/density_resources.cpp):
// from the eye over (screen, view depth), and from each beam's lens over (light-map u, v, r).
#include "interface.h"

layout(location = HAZE_LOC_DENSITY_ON) uniform int uDensityOn;
// A program built with STATIC_FEATURES for a frame without a field (no DENSITY_FIELD) has the
// field's code compiled out (shaders/interface.h, "Static features").
#if defined(STATIC_FEATURES) && !defined(DENSITY_FIELD)
#define DENSITY_ON false
#else
#define DENSITY_ON (uDensityOn != 0)
#endif
layout(location = HAZE_LOC_DENSITY_MIN) uniform vec3 uDensityMin;
layout(location = HAZE_LOC_DENSITY_INV_SIZE) uniform vec3 uDensityInvSize;
layout(location = HAZE_LOC_EYE_PATH_EYE) uniform vec3 uPathEye;
layout(location = HAZE_LOC_EYE_PATH_FORWARD) uniform vec3 uPathForward;
layout(location = HAZE_LOC_EYE_PATH_RIGHT_TAN) uniform vec3 uPathRightTan;
layout(location = HAZE_LOC_EYE_PATH_UP_TAN) uniform vec3 uPathUpTan;
layout(location = HAZE_LOC_EYE_PATH_DEPTH) uniform float uPathDepth;
layout(location = HAZE_LOC_LENS_PATH_GRID) uniform ivec4 uLensPathGrid;
layout(binding = HAZE_UNIT_DENSITY) uniform sampler3D uDensity;
layout(binding = HAZE_UNIT_EYE_PATH) uniform sampler3D uEyePath;
layout(binding = HAZE_UNIT_LENS_PATH) uniform sampler3D uLensPath;

float densityAt(vec3 x) {
  if (!DENSITY_ON) return 1.0;
  return texture(uDensity, (x - uDensityMin) * uDensityInvSize).r;
}

// The integral of D from the eye to x (only with DENSITY_ON: its uniforms are set only then). The map's slice k is view depth k * uPathDepth / (n - 1);
// beyond its last slice the path goes on at the density found there.
float eyePathTo(vec3 x) {
  vec3 d = x - uPathEye;
  float z = max(dot(d, uPathForward), 1e-6);
  vec2 ndc = vec2(dot(d, uPathRightTan) / dot(uPathRightTan, uPathRightTan),
                  dot(d, uPathUpTan) / dot(uPathUpTan, uPathUpTan)) / z;
  float n = float(textureSize(uEyePath, 0).z);
  float zc = min(z, uPathDepth);
  // The map holds the path over the length of its texel's ray of unit view depth.
  float len = length(d) / z;
  float path = texture(uEyePath, vec3(ndc * 0.5 + 0.5, (zc / uPathDepth * (n - 1.0) + 0.5) / n)).r * len;
  if (z > uPathDepth) path += (z - uPathDepth) * len * densityAt(x);
  return path;
}

// The integral of D from beam i's lens to the point at distance r in direction wl; uv is the
// light-map coordinate of wl (in [0, 1]^2, as beamIntensity looks it up), invReach is
// 1 / the beam's reach (its map's last slice). Only with DENSITY_ON.
float lensPathTo(int i, vec2 uv, float r, float invReach) {
  int tiles = uLensPathGrid.x, side = uLensPathGrid.z, slices = uLensPathGrid.w;
  vec2 tile = vec2(i % tiles, i / tiles);
  vec2 texel = tile * float(side) + clamp(uv * float(side), vec2(0.5), vec2(float(side) - 0.5));
  vec2 size = vec2(float(tiles), float(uLensPathGrid.y)) * float(side);
  float s = clamp(r * invReach, 0.0, 1.0) * float(slices - 1) + 0.5;
  float path = texture(uLensPath, vec3(texel / size, s / float(slices))).r;
  // Beyond the reach (past the last surface the beam sees: in shadow) at the mean density so far.
  float beyond = r - 1.0 / invReach;
  if (beyond > 0.0) path += beyond * path * invReach;
  return path;
}
