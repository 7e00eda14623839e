// The sun on the GPU (docs/rendering.md, "The sun"): an orthographic shadow map over the venue's
// bounding box, seen along the sun's direction, the uniforms that light surfaces with it
// (shaders/sun.glsl), and the march that adds its in-scattering into the beams' scattering
// buffer (shaders/sun_scatter.frag.glsl). Without a lit sun it does nothing and sets uSunOn = 0.
#pragma once

#include <memory>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "fixtures/core/result.h"
#include "renderer/gl/objects.h"
#include "renderer/density_resources.h"
#include "renderer/gpu_venue.h"
#include "shows/scene/frame_state.h"

namespace haze {

struct SunPassSettings {
  // The shadow map's side in texels; it spans the venue's box as seen from the sun, so its
  // texel is about the box's diagonal / mapSize (docs/rendering.md, "The sun").
  int mapSize = 2048;
  int steps = 96;  // march samples per eye ray and frame
};

class SunPass {
 public:
  static Result<SunPass> create(const SunPassSettings& settings);

  // Renders the shadow map when the sun's direction changed (or on the first lit frame), and
  // with a density field the sun's path map when the field or the direction changed.
  // Returns true when it rendered a shadow map.
  bool update(const FrameState& frame, const GpuVenue& venue, const gl::Program& depthProgram);
  bool lit() const { return lit_; }
  // Sets sun.glsl's uniforms on a program and binds the shadow map (uSunOn = 0 without a sun).
  void bind(GLuint program) const;
  // Adds one jittered frame of the sun's in-scattering into the bound target (blending on).
  void drawScatter(const FrameState& frame, float aspect, float frameJitter, const DensityResources& density) const;
  const SunPassSettings& settings() const { return settings_; }

 private:
  void updatePath(const FrameState& frame);
  SunPassSettings settings_;
  gl::Program scatter_;
  gl::Texture map_, path_;
  const DensityField* pathField_ = nullptr;  // what path_ holds, for pathDirection_
  std::shared_ptr<const DensityField> keepField_;
  glm::vec3 pathDirection_{0.0f};
  gl::Framebuffer fbo_;
  bool lit_ = false;
  bool haveMap_ = false;
  glm::vec3 mapDirection_{0.0f};
  glm::mat4 viewProj_{1.0f};
  glm::vec3 boxMin_{0.0f}, boxMax_{0.0f};
  SunState sun_;
};

}  // namespace haze
