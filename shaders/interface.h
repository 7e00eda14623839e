// The one contract between the C++ renderer and the GLSL in shaders/: uniform locations, texture
// units, storage-buffer bindings, enum values and the storage buffers' structs. This file is
// read by both compilers (C++ includes it as "shaders/interface.h", GLSL as "interface.h"
// through renderer/gl/program.cpp's resolver), so a number lives here once and both sides use
// its name: a binding that changes on one side cannot silently disagree with the other.
//
// Only the preprocessor is common to both languages: numbers are #defines (GLSL's layout()
// takes them), C++-only parts sit in `#ifdef __cplusplus`. Include guards rather than
// #pragma once, since GLSL has no #pragma once.
#ifndef HAZE_SHADERS_INTERFACE_H
#define HAZE_SHADERS_INTERFACE_H

// ---- Vertex inputs (venue.vert.glsl; renderer/gpu_venue.cpp) -------------------------------
#define HAZE_ATTR_POSITION 0
#define HAZE_ATTR_NORMAL 1
#define HAZE_ATTR_UV 2

// Every pass but the surfaces' G-buffer draws into one colour attachment.
#define HAZE_FRAG_OUT 0

// ---- Texture units ------------------------------------------------------------------------
// One unit per texture across all passes, so binding one pass's input never replaces another's.
#define HAZE_UNIT_RADIANCE 0        // post.frag.glsl: the radiometric image, nearest
#define HAZE_UNIT_LIGHT_MAPS 1      // beams.glsl: I * gobo * gate per beam (array layers)
#define HAZE_UNIT_SHADOW_MAPS 2     // beams.glsl: depth from each lens (array layers)
#define HAZE_UNIT_BASE_TEXTURE 3    // surface.frag.glsl
#define HAZE_UNIT_EMISSIVE_TEXTURE 4
#define HAZE_UNIT_SCENE_DEPTH 5     // camera.glsl: the full-resolution depth buffer
#define HAZE_UNIT_SCATTER 6         // composite.frag.glsl: accumulated in-scattering
#define HAZE_UNIT_SCATTER_DEPTH 7   // composite.frag.glsl: view depth per scattering texel
#define HAZE_UNIT_RADIANCE_MIPS 8   // post.frag.glsl: the radiance again, trilinear (bloom)
#define HAZE_UNIT_DENSITY 9         // density.glsl: D(x) on its grid (3D, trilinear, clamped to edge)
#define HAZE_UNIT_EYE_PATH 10       // density.glsl: the integral of D from the eye, over screen x view depth
#define HAZE_UNIT_LENS_PATH 11      // density.glsl: the integral of D from each lens, over light-map (u, v) x r
#define HAZE_UNIT_SCATTER_FINE 12   // composite.frag.glsl: full-resolution in-scattering where refined
#define HAZE_UNIT_REFINE_MASK 13    // composite.frag.glsl: 1 where the pixel was refined
#define HAZE_UNIT_SHADOW_DEPTH 14   // beams.glsl: the shadow maps again, raw depth (no compare; soft shadows' blocker search)
#define HAZE_UNIT_SUN_SHADOW 15     // sun.glsl: depth seen from the sun (orthographic over the venue's box)
#define HAZE_UNIT_SUN_PATH 16       // sun.glsl: the integral of D towards the sun, over the density grid
#define HAZE_UNIT_PARTICLES 17      // particles.vert.glsl: RGBA32F texture buffer, two texels per particle
#define HAZE_UNIT_SHADOW_MIN 20     // beams.glsl: the shadow maps' least depths (shows/scene/depth_pyramid.h), R32F array, its levels side by side in level 0
// surface.frag.glsl: the surfaces' attributes per pixel from gbuffer.frag.glsl (RGBA32UI): the
// normal (octahedral, two snorm16), albedo and emission (half floats); the position is the scene
// depth's, so the G-buffer adds 16 bytes a pixel
#define HAZE_UNIT_GBUFFER 18
// No image units are used.

// ---- Shader storage buffer bindings -------------------------------------------------------
#define HAZE_SSBO_BEAMS 0        // struct Beam[] (below), written by renderer/beam_resources.cpp
#define HAZE_SSBO_TILE_MASKS 3   // uint[]: the light tiles' beam masks (below)

// ---- Uniform locations --------------------------------------------------------------------
// Locations are per program: each block names the program(s) or include file that declares
// them. Blocks that are linked into one program must not overlap (camera.glsl and phase.glsl
// are included next to every other block, hence their high numbers).

// venue.vert.glsl (shadow maps, depth pre-pass, surfaces)
#define HAZE_LOC_VIEW_PROJ 0
#define HAZE_LOC_MODEL 12   // mat4 (12..15): a body mesh's placement; identity (its default) for the venue

// surface.frag.glsl (a full-screen pass, with camera.glsl; the material's four are gbuffer.frag.glsl's,
// with venue.vert.glsl)
#define HAZE_LOC_SURFACE_SIGMA_T 2
#define HAZE_LOC_SURFACE_AMBIENT 3
#define HAZE_LOC_SURFACE_BASE_COLOR 4
#define HAZE_LOC_SURFACE_EMISSIVE 5
#define HAZE_LOC_SURFACE_HAS_BASE_TEXTURE 6
#define HAZE_LOC_SURFACE_HAS_EMISSIVE_TEXTURE 7
#define HAZE_LOC_SURFACE_BEAM_COUNT 8
#define HAZE_LOC_SURFACE_TILE_COLUMNS 9   // 0: no tile masks, every beam is tried
#define HAZE_LOC_SURFACE_MASK_WORDS 10

// camera.glsl (every full-screen and compute pass)
#define HAZE_LOC_CAMERA_EYE 20
#define HAZE_LOC_CAMERA_FORWARD 21
#define HAZE_LOC_CAMERA_RIGHT_TAN 22
#define HAZE_LOC_CAMERA_UP_TAN 23
#define HAZE_LOC_CAMERA_NEAR_FAR 24

// phase.glsl
#define HAZE_LOC_PHASE 25   // one of HAZE_PHASE_*
#define HAZE_LOC_PHASE_G 26

// scatter.glsl (the virtual planes program)
#define HAZE_LOC_SCATTER_DEPTH_RANGE 1
#define HAZE_LOC_SCATTER_BEAM 2
#define HAZE_LOC_SCATTER_SIGMA_S 3
#define HAZE_LOC_SCATTER_SIGMA_T 4
#define HAZE_LOC_SCATTER_TARGET_SIZE 5
#define HAZE_LOC_SCATTER_FRAME_JITTER 6
#define HAZE_LOC_SCATTER_JITTER 7
#define HAZE_LOC_SCATTER_PLANES 8
#define HAZE_LOC_SCATTER_MIN_SAMPLES 9
#define HAZE_LOC_SCATTER_LATTICE 10

// planes.vert.glsl: the footprint polygon takes HAZE_FOOTPRINT_MAX_VERTICES locations
// from HAZE_LOC_PLANES_POLYGON_NDC on (30 to 53).
#define HAZE_LOC_PLANES_RECT_NDC 0
#define HAZE_LOC_PLANES_POLYGON_NDC 30
#define HAZE_FOOTPRINT_MAX_VERTICES 24

// lens.vert.glsl / lens.frag.glsl (the lens discs; with camera.glsl)
#define HAZE_LOC_LENS_VIEW_PROJ 0
#define HAZE_LOC_LENS_SIGMA_T 1

// composite.frag.glsl
#define HAZE_LOC_COMPOSITE_SCALE 0
#define HAZE_LOC_COMPOSITE_UPSAMPLE 1
#define HAZE_LOC_COMPOSITE_REFINE 2     // int: 1 = take the refined pixels from HAZE_UNIT_SCATTER_FINE

// refine_mask.frag.glsl
#define HAZE_LOC_REFINE_CONTRAST 0      // float: the relative curvature that refines
#define HAZE_LOC_REFINE_FLOOR 1         // float: ... where the brightest neighbour is above this x the frame's mean

// post.frag.glsl
#define HAZE_LOC_POST_EXPOSURE 0
#define HAZE_LOC_POST_BLOOM 1

// light_tiles.comp.glsl
#define HAZE_LOC_TILES_TARGET_SIZE 0
#define HAZE_LOC_TILES_BEAM_COUNT 1
#define HAZE_LOC_TILES_MASK_WORDS 2
#define HAZE_LOC_TILES_GRID 3   // columns, rows

// density.glsl (with surface, lens and virtual-plane programs; docs/rendering.md, "Density")
#define HAZE_LOC_DENSITY_ON 60          // int: 0 = the uniform medium (D = 1, no lookups)
#define HAZE_LOC_DENSITY_MIN 61         // vec3: the grid's lower corner
#define HAZE_LOC_DENSITY_INV_SIZE 62    // vec3: 1 / the grid's extent
#define HAZE_LOC_EYE_PATH_EYE 63        // vec3
#define HAZE_LOC_EYE_PATH_FORWARD 64    // vec3, unit
#define HAZE_LOC_EYE_PATH_RIGHT_TAN 65  // vec3: right * tan(fov_x / 2)
#define HAZE_LOC_EYE_PATH_UP_TAN 66     // vec3: up * tan(fov_y / 2)
#define HAZE_LOC_EYE_PATH_DEPTH 67      // float: the view depth of the map's last slice
#define HAZE_LOC_LENS_PATH_GRID 68      // ivec4: tiles across, tiles down, texels per tile side, r slices

// beams.glsl's soft shadows (with the surface and virtual-plane programs; 71..74 free for them)
#define HAZE_LOC_SOFT_SHADOWS 70        // int: 1 = V(x) is the visible fraction of the lens disc
#define HAZE_LOC_SHADOW_MIN_ON 97       // int: 1 = skip the shadow taps where HAZE_UNIT_SHADOW_MIN proves them all lit
// The depth pyramid's finest cells, 2^shift shadow-map texels (kDepthPyramidFirstShift).
#define HAZE_SHADOW_MIN_FIRST_SHIFT 3
// sun.glsl (with the surface program and sun_scatter.frag.glsl; docs/rendering.md, "The sun")
#define HAZE_LOC_SUN_ON 75           // int: 0 = no sun (nothing of the sun is evaluated)
#define HAZE_LOC_SUN_DIRECTION 76    // vec3, unit: the way the sun's light travels
#define HAZE_LOC_SUN_ILLUMINANCE 77  // vec3: c * E [lux]
#define HAZE_LOC_SUN_VIEW_PROJ 78    // mat4 (78..81): world to the sun's shadow map
#define HAZE_LOC_SUN_BOX_MIN 82      // vec3: the sun's medium (the venue's bounding box)
#define HAZE_LOC_SUN_BOX_MAX 83      // vec3
#define HAZE_LOC_SUN_MARCH 84        // vec4 (sun_scatter.frag.glsl): sigma_s, sigma_t, steps, frame jitter
// particles.vert.glsl / particles.frag.glsl (visible dust; with beams, camera, phase and density)
#define HAZE_LOC_PARTICLES_VIEW_PROJ 85   // mat4 (85..88)
#define HAZE_LOC_PARTICLES_SIGMA_T 89     // float
#define HAZE_LOC_PARTICLES_SPRITE 90      // vec4: kernel radius (px), 1 / a pixel's solid angle on the axis (1/sr), display gain, 0

// ---- Static features -------------------------------------------------------------------
// Programs built with STATIC_FEATURES (the virtual planes and the surface lighting,
// renderer/shader_features.h) have the frame's switches compiled in: DENSITY_FIELD, SUN and
// SOFT_SHADOWS when the frame has them, PHASE_KIND its HAZE_PHASE_*. Without one, that code is
// left out, not skipped at run time: llvmpipe runs both sides of a branch, so a uniform's `if`
// costs every sample. The others read the switches from their uniforms.

// ---- Enums --------------------------------------------------------------------------------
// haze::Phase (shows/scene/frame_state.h) asserts its values against these.
#define HAZE_PHASE_HAZY 0
#define HAZE_PHASE_ISOTROPIC 1
#define HAZE_PHASE_HENYEY_GREENSTEIN 2

// ---- Light tiles --------------------------------------------------------------------------
// The screen is cut into HAZE_TILE_PX square tiles, row-major from the bottom left; tile t's
// mask words are tileMasks[t * maskWords + w], bit k of word w standing for beam 32 w + k.
#define HAZE_TILE_PX 4    // llvmpipe shades 4x4 blocks: a tile is one block's mask (docs/rendering.md)
#define HAZE_TILE_GROUP_X 8   // tiles per compute work group (one invocation per tile)

// ---- struct Beam: one element of the beams storage buffer (std430) --------------------------
// The same declaration compiles in both languages: C++ sees glm types under GLSL's names.
#ifdef __cplusplus
#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
namespace haze::gpu {
using vec4 = glm::vec4;
using mat4 = glm::mat4;
#endif

struct Beam {
  vec4 lensPos;   // xyz lens position, w = cos(cutoff half-angle)
  vec4 xb;        // xyz reference axis, w = 1 / (tan(F/2) * light-map extent)
  vec4 yb;        // xyz, w = light-map layer
  vec4 zb;        // xyz beam axis, w = shadow-map layer
  vec4 color;     // rgb = dimmer * colour filter, w = tan(cutoff)
  mat4 shadowViewProj;
  vec4 lens;      // x = r_lens, y = 1 / (pi r_lens^2), z = cos^2 of the core half-angle (0: no core), w = 1 / reach (m)
};

// The std430 offsets of struct Beam's fields: the C++ compiler lays out glm types by its own
// rules, so each field is checked against the offset GLSL gives it.
#define HAZE_BEAM_OFFSET_LENS_POS 0
#define HAZE_BEAM_OFFSET_XB 16
#define HAZE_BEAM_OFFSET_YB 32
#define HAZE_BEAM_OFFSET_ZB 48
#define HAZE_BEAM_OFFSET_COLOR 64
#define HAZE_BEAM_OFFSET_SHADOW_VIEW_PROJ 80
#define HAZE_BEAM_OFFSET_LENS 144
#define HAZE_BEAM_SIZE 160

#ifdef __cplusplus
static_assert(offsetof(Beam, lensPos) == HAZE_BEAM_OFFSET_LENS_POS);
static_assert(offsetof(Beam, xb) == HAZE_BEAM_OFFSET_XB);
static_assert(offsetof(Beam, yb) == HAZE_BEAM_OFFSET_YB);
static_assert(offsetof(Beam, zb) == HAZE_BEAM_OFFSET_ZB);
static_assert(offsetof(Beam, color) == HAZE_BEAM_OFFSET_COLOR);
static_assert(offsetof(Beam, shadowViewProj) == HAZE_BEAM_OFFSET_SHADOW_VIEW_PROJ);
static_assert(offsetof(Beam, lens) == HAZE_BEAM_OFFSET_LENS);
static_assert(sizeof(Beam) == HAZE_BEAM_SIZE);
}  // namespace haze::gpu
#endif

#endif  // HAZE_SHADERS_INTERFACE_H
