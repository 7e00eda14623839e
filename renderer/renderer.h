// The GPU renderer: takes a Venue once and a FrameState per frame, draws into a float radiance
// target (docs/physics.md's L per pixel), and encodes it for display. Passes: shadow maps (cached per
// beam), surfaces, volumetric beams, post. Needs a current OpenGL 4.5 context (renderer/context.h).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "fixtures/core/result.h"
#include "shows/scene/exposure.h"
#include "shows/scene/frame_state.h"
#include "shows/scene/image.h"
#include "shows/scene/venue.h"

namespace haze {

struct RenderSettings {
  int width = 1280;
  int height = 720;
  int lightMapSize = 512;
  int shadowMapSize = 1024;
  int planes = 48;          // virtual planes per beam
  int scatterDivisor = 1;   // scattering buffer at 1/n resolution, depth-aware upsample
  float refineCurvature = 0.0f;  // see BeamPassSettings::refineCurvature (0 = no refinement)
  float refineFloor = 0.0f;      // see BeamPassSettings::refineFloor
  int frames = 1;           // jittered frames accumulated per render
  bool jitter = true;
  bool fusedPlanes = true;  // see BeamPassSettings::fused
  int minSamplesPerChord = 8;
  int lattice = 0;          // see BeamPassSettings::lattice
  int sunMapSize = 2048;    // the sun's shadow map (SunPassSettings::mapSize)
  int sunSteps = 96;        // the sun's march samples per eye ray and frame
  // Surfaces loop only over the beams that reach their 4x4 tile (renderer/light_tiles.h);
  // off, every pixel tries every beam (same image, for tests and the bench).
  bool tiledSurfaces = true;
  // Shadow lookups first ask the shadow maps' least-depth pyramid whether all their taps are
  // lit (shows/scene/depth_pyramid.h); off, every lookup takes its taps (same image, for
  // tests and the bench).
  bool shadowMinPyramid = true;
  // The frame's density field, sun, soft shadows and phase function compiled into the planes'
  // and the surfaces' programs (renderer/shader_features.h: llvmpipe runs both sides of a
  // branch on a uniform); off, read from uniforms (same image, for tests).
  bool staticFeatures = true;
  // Beams' shadow maps draw only the venue's chunks that their frustum reaches
  // (GpuVenue::drawInside); off, every chunk (same depths, for tests and the bench).
  bool cullVenueChunks = true;
  // Body meshes wholly outside the camera's frustum skipped and closed ones back-face culled in
  // the G-buffer pass (renderer/gpu_bodies.h); off, every part is drawn whole (the same
  // image, for tests and haze bench --compare-bodies).
  bool cullBodies = true;
  // All beams' shadow maps together, in texels (4 bytes each): with more beams than fit at
  // shadowMapSize, every map gets smaller (renderer/beam_resources.h).
  int64_t shadowTexelBudget = int64_t{32} << 20;
  // Times each pass with GL timer queries (lastTimes()); off, nothing waits on the GL.
  bool timePasses = false;
  // CPU wall time per render for redrawing changed shadow maps and baking changed light maps
  // (docs/rendering.md, "Map work spread over frames"): past it the remaining beams keep their
  // old maps until a later render, the longest waiting first, at least one map per render.
  // 0: every changed map in its render (a still image, the bench, tests).
  double mapWorkBudgetMs = 0.0;
};

struct DisplaySettings {
  // Display value = L * 2^exposureEv / kKeyNits before the tone curve: at EV 0 a surface of
  // 50 cd/m^2 maps to 1 (a lit stage deck). Always absolute: auto exposure (meter() and
  // shows/scene/exposure.h) is resolved by the caller into this number.
  float exposureEv = 0.0f;
  static constexpr float kKeyNits = kManualKeyNits;
  // Lens glare around bright beams and lamps: the fraction of the light spread over a wide
  // kernel (0 = off, 0.02-0.1 looks like a camera). Display only; readRadiance never has it.
  float bloom = 0.0f;
};

// What the last render did. The pass times are GL timer queries, filled only with
// RenderSettings::timePasses; post and meter are the CPU's, their readback included.
struct PassTimes {
  double shadowMapsMs = 0, surfacesMs = 0, beamsMs = 0, postMs = 0, meterMs = 0;
  int shadowMapsRendered = 0, lightMapsBaked = 0;
  bool sunMapRendered = false;
  int shadowMapSize = 0, lightMapLayers = 0;  // see BeamUpdateStats
  // Beams drawn with an out-of-date shadow or light map (RenderSettings::mapWorkBudgetMs); the
  // image is final only when this is 0.
  int mapsPending = 0;
  int beamsDrawn = 0;                // in-scattering footprints drawn (in view, lit)
  int bodyMeshesDrawn = 0;           // posed body meshes drawn by the camera (in its frustum)
  double beamsPerTile = 0;           // surfaces: beams tried per lit 4x4 tile (timePasses only)
  uint64_t planeFragments = 0;       // footprint pixels times planes (or walks, when fused)
  uint64_t scatteringFragments = 0;  // of those, the ones that added light (timePasses only)
  uint64_t refinedPixels = 0;        // rendered again at full resolution (timePasses only)
  int accumulatedFrames = 0;
  // Visible dust (docs/rendering.md, "Particles"), with FrameState::particles enabled only.
  double particlesMs = 0;             // the GL's part (timePasses only)
  double particlesGenerateMs = 0;     // the CPU's part: finding the particles in the cones
  size_t particlesDrawn = 0;          // sprites (a particle lit by two beams counts twice)
  size_t particlesWanted = 0;         // before the per-frame limit; above particlesDrawn: thinned
};

class Renderer {
 public:
  static Result<std::unique_ptr<Renderer>> create(const Venue& venue, const RenderSettings& settings);
  ~Renderer();

  // A new image size (a resized viewport): only the size-dependent targets are made again; the
  // programs, shadow maps and light maps are kept. The last render's image is lost.
  Status resize(int width, int height);

  // With accumulate, the beams' scattering of earlier renders is kept and one more jittered
  // set of frames is added (progressive refinement; the caller promises the frame is unchanged).
  void render(const FrameState& frame, bool accumulate = false);
  // The radiometric image of the last render, row 0 at the top.
  ImageRGB readRadiance() const;
  // Replaces the radiometric image with one made elsewhere (the CPU reference), so it goes
  // through the same display encoding. The image must have the renderer's size.
  void setRadiance(const ImageRGB& image);
  // The camera's light meter on the last render (docs/rendering.md, "Exposure"): the radiance's
  // mip chain is made on the GPU and one small level (about 80 texels across) is read back.
  Metering meter(const MeterSettings& settings = {});
  // The display encoding (8-bit sRGB, row 0 at the top) of the last render.
  std::vector<unsigned char> readDisplay(const DisplaySettings& display);
  // Draws the display encoding of the last render into the current framebuffer's viewport
  // (the window's back buffer in the GUI).
  void drawDisplay(const DisplaySettings& display, unsigned int framebuffer, int x, int y, int width, int height);
  const PassTimes& lastTimes() const { return times_; }
  // What the last render could not do (beams a GL limit left out, named by fixture id), one
  // line each; empty when it drew everything. Callers show these to the user.
  const std::vector<std::string>& warnings() const { return warnings_; }
  const RenderSettings& settings() const { return settings_; }
  // Changes RenderSettings::mapWorkBudgetMs from the next render on (0 catches up at once).
  void setMapWorkBudgetMs(double ms);

 private:
  struct Impl;
  explicit Renderer(std::unique_ptr<Impl> impl, const RenderSettings& settings);
  std::unique_ptr<Impl> impl_;
  RenderSettings settings_;
  PassTimes times_;
  std::vector<std::string> warnings_;
};

}  // namespace haze
