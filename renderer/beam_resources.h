// Per-beam GPU data: a light-map layer (I * gobo * gate over the (u, v) plane, from
// BeamOptics::bakeLightMap), a shadow-map layer (depth from the lens), and one entry of the
// beams storage buffer that every lighting shader reads. Light maps are re-baked only when a
// beam's opticsKey changes, shadow maps re-rendered only when its poseKey or cone changes or
// a body that can lie in its cone (shows/scene/body_shadow.h: another fixture's) moves.
//
// Memory is bounded (docs/rendering.md, "Large rigs"): beams with equal optics share one
// light-map layer, and the shadow maps' layer size shrinks so that all of them fit a texel
// budget. Beams beyond the GL's array-layer limit cannot be drawn; update() names them.
//
// Time is bounded on request (BeamResourceSettings::mapWorkBudgetMs, docs/rendering.md, "Map
// work spread over frames"): an interactive caller lets a cue that moves a whole rig redraw
// its maps over several frames, the beams that have waited longest first. Until its turn a
// beam keeps the maps it had, with the shadow matrix and reach its shadow map was drawn with,
// so that every lookup reads the map it indexes (the old pose's shadow).
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "renderer/gl/objects.h"
#include "renderer/gpu_bodies.h"
#include "renderer/gpu_venue.h"
#include "shows/scene/body_shadow.h"
#include "shows/scene/frame_state.h"
#include "shows/scene/map_schedule.h"
#include "shaders/interface.h"

namespace haze {

// One element of the beams storage buffer: the struct the shaders read (shaders/interface.h).
using GpuBeam = gpu::Beam;

struct BeamResourceSettings {
  int lightMapSize = 512;
  int shadowMapSize = 1024;  // per beam, while all of them fit the budget
  // The shadow maps' texels together (4 bytes each): more beams than fit at shadowMapSize get
  // smaller maps, all of one size (the array's layers).
  int64_t shadowTexelBudget = int64_t{32} << 20;
  bool shadowMinPyramid = true;  // RenderSettings::shadowMinPyramid
  // RenderSettings::mapWorkBudgetMs: 0 renders every changed map in its frame.
  double mapWorkBudgetMs = 0.0;
};

struct BeamUpdateStats {
  int lightMapsBaked = 0;
  int shadowMapsRendered = 0;
  int shadowMapSize = 0;  // the layers' size this frame (shadowMapSize or less, see the budget)
  int lightMapLayers = 0; // distinct light maps
  // Beams drawn with an out-of-date shadow or light map (the budget deferred their new one).
  int mapsPending = 0;
  // Fixture ids of the beams that could not be drawn (a GL limit), with the reason; empty
  // when every beam is drawn.
  std::vector<int> notDrawn;
  std::string notDrawnReason;
};

class BeamResources {
 public:
  explicit BeamResources(const BeamResourceSettings& settings);

  // Brings light maps, shadow maps and the storage buffer up to date with frame.beams; the
  // shadow maps hold the venue and the casters among `bodies` (updated with this frame's).
  BeamUpdateStats update(const FrameState& frame, const GpuVenue& venue, const GpuBodies& bodies,
                         const gl::Program& shadowProgram);

  // The storage buffer, light maps and shadow maps at their shaders/interface.h bindings.
  void bind() const;
  // The soft-shadow switch (FrameState::softShadows of the last update) and the least-depth
  // pyramid's on a program that includes beams.glsl and tests visibility.
  void bindSoftShadows(unsigned int program) const;
  bool softShadows() const { return softShadows_; }
  int count() const { return static_cast<int>(gpuBeams_.size()); }
  const std::vector<GpuBeam>& beams() const { return gpuBeams_; }
  const BeamResourceSettings& settings() const { return settings_; }
  void setMapWorkBudgetMs(double ms) { settings_.mapWorkBudgetMs = ms; }
  // Whether beam i has its maps this frame (false: a GL limit left it out; it adds nothing).
  bool drawn(int i) const { return drawn_[static_cast<size_t>(i)] != 0; }
  int drawnCount() const { return static_cast<int>(std::count(drawn_.begin(), drawn_.end(), 1)); }
  // How far from its lens beam i can light anything: the farthest surface its shadow map sees
  // inside the cone (the venue's far corner when some of the cone escapes to the sky). Beyond
  // it the cone is in shadow, so the planes pass need not cover it.
  float reachM(int i) const { return reachesM_[static_cast<size_t>(i)]; }

 private:
  // Makes the shadow-map array for `beams` layers of the budget's size (kept while both hold).
  void ensureShadowCapacity(int beams);
  // Makes the light-map array for `layers` distinct light maps; everything is baked again
  // unless `keep` (the old layers are copied over).
  void ensureLightCapacity(int layers, bool keep);
  // Draws a shadow map.
  void drawShadow(int layer, const glm::mat4& viewProj, const GpuVenue& venue, const GpuBodies& bodies,
                  const ShadowCasters& casters, const gl::Program& program);
  // Reads a drawn map back (waiting for it), makes its least-depth pyramid and returns the
  // beam's reach (see reachM).
  float readShadow(int layer, float nearM, float farM, float cutoffRad);

  // What one shadow map is drawn with.
  struct ShadowJob {
    float cutoff = 0.0f, farM = 0.0f;
    glm::mat4 viewProj{1.0f};
    ShadowCasters casters;
    uint64_t key = 0;
  };
  // One update's plan and the work it has done so far.
  struct UpdatePlan {
    const FrameState* frame;
    const GpuVenue* venue;
    const GpuBodies* bodies;
    const gl::Program* program;
    bool budgeted = false;
    std::vector<uint64_t> keys;                  // per beam: its light map's content
    std::unordered_map<uint64_t, int> layerOf;   // content -> its layer (-1: not baked yet)
    std::vector<int> freeLayers;
    std::vector<int> fallback;                   // per beam: an old layer it shows meanwhile, or -1
    std::vector<ShadowJob> shadowJobs;           // per beam within the shadow capacity
    std::vector<int> unread;                     // beams whose drawn shadow map is not read back yet
    BeamUpdateStats stats;
  };
  void assignLightLayers(UpdatePlan& plan);
  int fallbackLayer(const FrameState& frame, size_t beam) const;
  void planShadows(UpdatePlan& plan);
  std::vector<MapJob> doOrDefer(UpdatePlan& plan);
  void bake(UpdatePlan& plan, size_t beam);
  void drawNow(UpdatePlan& plan, int beam);
  void readUnread(UpdatePlan& plan);
  void writeGpuBeams(UpdatePlan& plan);
  void uploadBeams();

  BeamResourceSettings settings_;
  int maxLayers_ = 0;        // GL_MAX_ARRAY_TEXTURE_LAYERS
  int shadowCapacity_ = 0, shadowSize_ = 0, lightCapacity_ = 0, ssboCapacity_ = 0;
  gl::Texture lightMaps_;
  gl::Texture shadowMaps_;
  // Per shadow layer, its least depths over blocks (shows/scene/depth_pyramid.h), R32F mips.
  gl::Texture shadowMin_;
  gl::Buffer ssbo_;
  gl::Framebuffer shadowFbo_{"shadow_fbo"};
  // Reads the shadow maps' raw depths (no compare, nearest) for the soft shadows' blocker search.
  gl::Sampler shadowDepthSampler_{"shadow_depths"};
  bool softShadows_ = false;
  std::vector<uint64_t> lightKeys_;    // per light-map layer, what is baked there (0: nothing)
  std::vector<float> extents_;         // per light-map layer
  std::vector<float> lightScales_;     // per light-map layer: GpuBeam::xb.w of the beams it was baked for
  std::vector<uint64_t> shadowKeys_;   // per beam (= shadow layer); 0: no map
  std::vector<float> reachesM_;        // per beam
  // Per shadow layer: the matrix its map was drawn with and the fixture it belongs to.
  std::vector<glm::mat4> shadowViewProjs_;
  std::vector<int> shadowFixtures_;
  // Per beam: the update since which its shadow map, or its light map, has been out of date.
  std::vector<uint64_t> shadowStaleSince_, lightStaleSince_;
  // Per beam: the light-map layer it was last drawn with, what that layer held then, and the
  // fixture (a beam's old light map is its fallback only while both still hold).
  std::vector<int> drawnLightLayers_;
  std::vector<uint64_t> drawnLightKeys_;
  std::vector<int> drawnLightFixtures_;
  uint64_t updates_ = 0;
  MapSchedule schedule_;                // the deferred maps' order and budget
  std::vector<char> drawn_;            // per beam
  std::vector<float> coreCos2_;        // per light-map layer: the map's core (beam_resources.cpp)
  std::vector<float> depthScratch_;
  std::vector<GpuBeam> gpuBeams_;
};

}  // namespace haze
