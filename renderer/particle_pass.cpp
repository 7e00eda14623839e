#include "renderer/gl/scope.h"
#include "renderer/particle_pass.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include <glm/common.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/trigonometric.hpp>

#include "renderer/camera_uniforms.h"
#include "renderer/gl/program.h"
#include "shaders/interface.h"

namespace haze {
namespace {

// The kernel's radius in pixels: a particle is far below a pixel, so its light is spread over
// a few, as a lens's blur and the eye's would (docs/rendering.md, "Particles").
constexpr float kSpriteRadiusPx = 1.5f;

}  // namespace

Result<ParticlePass> ParticlePass::create() {
  ParticlePass pass;
  auto program = gl::buildProgram({.label = "particles", .vertex = "particles.vert.glsl", .fragment = "particles.frag.glsl"});
  if (!program) return program.error();
  pass.program_ = std::move(*program);
  return pass;
}

ParticleStats ParticlePass::render(const FrameState& frame, const BeamResources& beams,
                                   const DensityResources& density, const glm::mat4& viewProj, float aspect,
                                   int width, int height, const glm::vec3& boundsMin, const glm::vec3& boundsMax) {
  ParticleStats stats;
  if (!frame.particles.settings.enabled || beams.count() == 0) return stats;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<ParticleCone> cones;
  for (int i = 0; i < beams.count(); ++i) {
    const GpuBeam& g = beams.beams()[static_cast<size_t>(i)];
    // A dark beam (dimmer 0 or a black filter) lights no dust; neither does one a GL limit left out.
    if (!beams.drawn(i) || std::max({g.color.r, g.color.g, g.color.b}) <= 0.0f) continue;
    cones.push_back({.apex = glm::vec3(g.lensPos), .axis = glm::vec3(g.zb),
                     .halfAngleRad = std::acos(std::clamp(g.lensPos.w, -1.0f, 1.0f)), .lengthM = beams.reachM(i),
                     .beam = i});
  }
  // Dust fills the room: the venue's box, grown to hold the lenses and the camera (a venue of
  // a floor alone is flat).
  glm::vec3 lo = glm::min(boundsMin, frame.camera.position), hi = glm::max(boundsMax, frame.camera.position);
  for (const ParticleCone& c : cones) {
    lo = glm::min(lo, c.apex);
    hi = glm::max(hi, c.apex);
  }
  const DensityField* field = frame.medium.density ? frame.medium.density.get() : nullptr;
  const ParticleSet set = generateParticles(frame.particles, cones, field, lo, hi);
  stats.drawn = set.particles.size();
  stats.wanted = set.wanted;
  stats.cellsTried = set.cellsTried;
  stats.generateMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (set.particles.empty()) return stats;

  std::vector<glm::vec4> texels;
  texels.reserve(set.particles.size() * 2);
  for (const Particle& p : set.particles) {
    texels.emplace_back(p.positionM, p.crossSectionM2);
    texels.emplace_back(static_cast<float>(p.beam), 0.0f, 0.0f, 0.0f);
  }
  if (texels.size() > capacity_) {
    capacity_ = std::max(texels.size(), capacity_ * 2);
    buffer_ = gl::Buffer("particles");
    glNamedBufferStorage(buffer_.id(), static_cast<GLsizeiptr>(capacity_ * sizeof(glm::vec4)), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
    texture_ = gl::Texture(GL_TEXTURE_BUFFER, "particles");
    glTextureBuffer(texture_.id(), GL_RGBA32F, buffer_.id());
  }
  glNamedBufferSubData(buffer_.id(), 0, static_cast<GLsizeiptr>(texels.size() * sizeof(glm::vec4)), texels.data());

  const GLuint prog = program_.id();
  glUseProgram(prog);
  glProgramUniformMatrix4fv(prog, HAZE_LOC_PARTICLES_VIEW_PROJ, 1, GL_FALSE, glm::value_ptr(viewProj));
  glProgramUniform1f(prog, HAZE_LOC_PARTICLES_SIGMA_T, frame.medium.extinction());
  const float tanY = std::tan(glm::radians(frame.camera.fovYDeg) * 0.5f), tanX = tanY * aspect;
  const float pixelSr = 4.0f * tanX * tanY / (static_cast<float>(width) * static_cast<float>(height));
  glProgramUniform4f(prog, HAZE_LOC_PARTICLES_SPRITE, kSpriteRadiusPx, 1.0f / pixelSr,
                     frame.particles.settings.brightness, 0.0f);
  setCameraUniforms(prog, frame.camera, aspect);
  glProgramUniform1i(prog, HAZE_LOC_PHASE, static_cast<int>(frame.medium.phase));  // Phase's values are HAZE_PHASE_*
  glProgramUniform1f(prog, HAZE_LOC_PHASE_G, frame.medium.g);
  density.bind(prog);
  beams.bind();
  glBindTextureUnit(HAZE_UNIT_PARTICLES, texture_.id());

  // Tested against the scene's depth, not written: the dust adds light over it.
  gl::Capability depthTest(GL_DEPTH_TEST, true), blend(GL_BLEND, true), pointSize(GL_PROGRAM_POINT_SIZE, true);
  gl::DepthMask noWrites(false);
  glDepthFunc(GL_LESS);
  glBlendFunc(GL_ONE, GL_ONE);
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(set.particles.size()));
  return stats;
}

}  // namespace haze
