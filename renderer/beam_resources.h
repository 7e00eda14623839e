// Per-beam GPU data: a light-map layer (I * gobo * gate over the (u, v) plane, from
// BeamOptics::bakeLightMap), a shadow-map layer (depth from the lens), and one entry of the
// beams storage buffer that every lighting shader reads. Light maps are re-baked only when a
// beam's opticsKey changes, shadow maps re-rendered only when its poseKey or cone changes.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "renderer/gl/objects.h"
#include "renderer/gpu_venue.h"
#include "renderer/scene/frame_state.h"
#include "shaders/interface.h"

namespace haze {

// One element of the beams storage buffer: the struct the shaders read (shaders/interface.h).
using GpuBeam = gpu::Beam;

struct BeamResourceSettings {
  int lightMapSize = 512;
  int shadowMapSize = 1024;
};

struct BeamUpdateStats {
  int lightMapsBaked = 0;
  int shadowMapsRendered = 0;
};

class BeamResources {
 public:
  explicit BeamResources(const BeamResourceSettings& settings);

  // Brings light maps, shadow maps and the storage buffer up to date with frame.beams.
  BeamUpdateStats update(const FrameState& frame, const GpuVenue& venue, const gl::Program& shadowProgram);

  // The storage buffer, light maps and shadow maps at their shaders/interface.h bindings.
  void bind() const;
  int count() const { return static_cast<int>(gpuBeams_.size()); }
  const std::vector<GpuBeam>& beams() const { return gpuBeams_; }
  const BeamResourceSettings& settings() const { return settings_; }
  // How far from its lens beam i can light anything: the farthest surface its shadow map sees
  // inside the cone (the venue's far corner when some of the cone escapes to the sky). Beyond
  // it the cone is in shadow, so the planes pass need not cover it.
  float reachM(int i) const { return reachesM_[static_cast<size_t>(i)]; }

 private:
  void ensureCapacity(int beams);
  // Renders a shadow map and returns the beam's reach (see reachM).
  float renderShadow(int layer, const glm::mat4& viewProj, float nearM, float farM, float cutoffRad,
                     const GpuVenue& venue, const gl::Program& program);

  BeamResourceSettings settings_;
  int capacity_ = 0;
  gl::Texture lightMaps_;
  gl::Texture shadowMaps_;
  gl::Buffer ssbo_;
  gl::Framebuffer shadowFbo_{"shadow_fbo"};
  std::vector<uint64_t> opticsKeys_;   // per layer, what is baked there
  std::vector<uint64_t> shadowKeys_;
  std::vector<float> extents_;
  std::vector<float> coreCos2_;  // per layer: the light map's core (beam_resources.cpp)
  std::vector<float> reachesM_;
  std::vector<float> depthScratch_;
  std::vector<GpuBeam> gpuBeams_;
};

}  // namespace haze
