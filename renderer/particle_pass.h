// Visible dust in the beams (docs/rendering.md, "Particles"): after the in-scattering is
// composited, each particle inside a beam's cone (shows/scene/particles.h, found on the CPU
// per beam) is drawn as a point sprite with the scene's depth test and added onto the radiance.
// A display option: nothing is drawn unless frame.particles.settings.enabled.
#pragma once

#include <cstddef>

#include <glm/mat4x4.hpp>

#include "fixtures/core/result.h"
#include "renderer/beam_resources.h"
#include "renderer/density_resources.h"
#include "renderer/gl/objects.h"
#include "shows/scene/frame_state.h"

namespace haze {

struct ParticleStats {
  size_t drawn = 0;   // sprites drawn (a particle lit by two beams is two)
  size_t wanted = 0;  // before the frame's limit (ParticleState::limit)
  size_t cellsTried = 0;
  double generateMs = 0.0;  // the CPU's part: finding the particles
};

class ParticlePass {
 public:
  static Result<ParticlePass> create();

  // Draws into the framebuffer bound now (the radiance with the scene's depth attached).
  ParticleStats render(const FrameState& frame, const BeamResources& beams, const DensityResources& density,
                       const glm::mat4& viewProj, float aspect, int width, int height, const glm::vec3& boundsMin,
                       const glm::vec3& boundsMax);

 private:
  gl::Program program_;
  gl::Buffer buffer_{"particles"};
  gl::Texture texture_;
  gl::VertexArray vao_{"particles_vao"};
  size_t capacity_ = 0;  // texels the buffer holds
};

}  // namespace haze
