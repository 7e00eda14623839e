// The density field on the GPU (docs/rendering.md, "Density"): D(x) as a 3D texture, and two
// maps of optical paths (integrals of D) made on the CPU from the same field, so that a sample
// costs one lookup per path instead of a march: from the eye over the screen and view depth,
// and from each beam's lens over its light map's (u, v) and the distance r. Each is made again
// only when what it depends on changes (the field, the camera, a beam's pose or reach).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "renderer/beam_resources.h"
#include "renderer/gl/objects.h"
#include "shows/scene/frame_state.h"

namespace haze {

class DensityResources {
 public:
  // Brings the textures up to date with frame.medium.density (none: nothing to do, the
  // shaders take the uniform medium). beams must be updated for this frame already.
  void update(const FrameState& frame, float aspect, const BeamResources& beams);
  bool on() const { return on_; }
  // Binds the textures and sets density.glsl's uniforms on a program that includes it.
  void bind(unsigned int program) const;
  // The integral of D along the view axis from the eye to far (the background's attenuation).
  float backgroundPath() const { return backgroundPath_; }

 private:
  bool on_ = false;
  const DensityField* field_ = nullptr;  // what the textures hold
  std::shared_ptr<const DensityField> keep_;
  gl::Texture density_, eyePath_, lensPath_;
  glm::vec3 min_{0.0f}, invSize_{1.0f};
  // The eye map's camera and depth.
  glm::vec3 eye_{0.0f}, forward_{0.0f, 0.0f, -1.0f}, rightTan_{1.0f, 0.0f, 0.0f}, upTan_{0.0f, 1.0f, 0.0f};
  float pathDepth_ = 1.0f, backgroundPath_ = 0.0f;
  uint64_t eyeKey_ = 0, lensKey_ = 0;
  int tiles_ = 1, tilesDown_ = 1, side_ = 32, slices_ = 64;
  std::vector<float> scratch_;
};

}  // namespace haze
