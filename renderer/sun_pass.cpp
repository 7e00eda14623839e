#include "renderer/gl/scope.h"
#include "renderer/sun_pass.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "renderer/camera_uniforms.h"
#include "renderer/gl/program.h"
#include "shows/scene/physics.h"
#include "shaders/interface.h"

namespace haze {
namespace {

// World to the map's clip space: looking along the sun's direction, the box's eight corners
// fitted tightly in x and y, with a margin in depth so no corner sits on a clip plane.
glm::mat4 sunViewProjection(const glm::vec3& d, const glm::vec3& lo, const glm::vec3& hi) {
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float radius = std::max(0.5f * glm::length(hi - lo), 0.01f);
  const glm::vec3 up = std::fabs(d.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  const glm::mat4 view = glm::lookAt(centre - d * (2.0f * radius), centre, up);
  glm::vec3 vmin(1e30f), vmax(-1e30f);
  for (int c = 0; c < 8; ++c) {
    const glm::vec3 corner((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
    const glm::vec3 p = glm::vec3(view * glm::vec4(corner, 1.0f));
    vmin = glm::min(vmin, p);
    vmax = glm::max(vmax, p);
  }
  // The map's edges are the box's own (sun.glsl clamps lookups half a texel inside them, so a
  // wall on the box's face that the sun grazes keeps its texels); a small margin only keeps a
  // flat venue's map from being degenerate, and the box off the depth range's clip planes.
  const float pad = 1e-4f * radius + 1e-4f, depthPad = 0.01f * radius + 1e-3f;
  // View space looks down -z: near and far are distances, -vmax.z and -vmin.z.
  return glm::ortho(vmin.x - pad, vmax.x + pad, vmin.y - pad, vmax.y + pad, -vmax.z - depthPad,
                    -vmin.z + depthPad) * view;
}

}  // namespace

Result<SunPass> SunPass::create(const SunPassSettings& settings) {
  SunPass p;
  p.settings_ = settings;
  p.settings_.mapSize = std::clamp(settings.mapSize, 64, 8192);
  p.settings_.steps = std::clamp(settings.steps, 1, 4096);
  auto scatter = gl::buildProgram({.label = "sun_scatter", .vertex = "fullscreen.vert.glsl",
                                   .fragment = "sun_scatter.frag.glsl"});
  if (!scatter) return scatter.error();
  p.scatter_ = std::move(*scatter);
  p.fbo_ = gl::Framebuffer("sun_shadow_fbo");
  return p;
}

// The sun's path map: at each cell centre of the density field's grid, the integral of D from
// there towards the sun to the edge of the venue's box, on the CPU (the field's own integral).
void SunPass::updatePath(const FrameState& frame) {
  const DensityField* field = frame.medium.density.get();
  if (!field || field->values.empty()) {
    keepField_.reset();
    pathField_ = nullptr;
    return;
  }
  if (field == pathField_ && pathDirection_ == frame.sun.direction) return;
  const int nx = field->nx, ny = field->ny, nz = field->nz;
  std::vector<float> values(static_cast<size_t>(nx) * ny * nz);
  const glm::vec3 cell = (field->maxM - field->minM) / glm::vec3(nx, ny, nz);
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const glm::vec3 c = field->minM + (glm::vec3(x, y, z) + 0.5f) * cell;
        const float s = sunPathInBox(c, frame.sun.direction, boxMin_, boxMax_);
        values[(static_cast<size_t>(z) * ny + y) * nx + x] = s > 0.0f ? field->integral(c, c - frame.sun.direction * s) : 0.0f;
      }
  int w = 0, h = 0, d = 0;
  if (path_) {
    glGetTextureLevelParameteriv(path_.id(), 0, GL_TEXTURE_WIDTH, &w);
    glGetTextureLevelParameteriv(path_.id(), 0, GL_TEXTURE_HEIGHT, &h);
    glGetTextureLevelParameteriv(path_.id(), 0, GL_TEXTURE_DEPTH, &d);
  }
  if (!path_ || w != nx || h != ny || d != nz) {
    path_ = gl::Texture(GL_TEXTURE_3D, "sun_path");
    glTextureStorage3D(path_.id(), 1, GL_R32F, nx, ny, nz);
    glTextureParameteri(path_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(path_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
      glTextureParameteri(path_.id(), wrap, GL_CLAMP_TO_EDGE);
  }
  glTextureSubImage3D(path_.id(), 0, 0, 0, 0, nx, ny, nz, GL_RED, GL_FLOAT, values.data());
  keepField_ = frame.medium.density;
  pathField_ = field;
  pathDirection_ = frame.sun.direction;
}

bool SunPass::update(const FrameState& frame, const GpuVenue& venue, const gl::Program& depthProgram) {
  sun_ = frame.sun;
  lit_ = frame.sun.lit();
  if (!lit_) return false;
  boxMin_ = venue.boundsMin();
  boxMax_ = venue.boundsMax();
  updatePath(frame);
  if (haveMap_ && mapDirection_ == frame.sun.direction) return false;
  if (!map_) {  // made on the first lit frame: a show without a sun never allocates it
    map_ = gl::Texture(GL_TEXTURE_2D, "sun_shadow_map");
    glTextureStorage2D(map_.id(), 1, GL_DEPTH_COMPONENT32F, settings_.mapSize, settings_.mapSize);
    glTextureParameteri(map_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(map_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(map_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(map_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(map_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(map_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, map_.id(), 0);
    glNamedFramebufferDrawBuffer(fbo_.id(), GL_NONE);
  }
  viewProj_ = sunViewProjection(frame.sun.direction, boxMin_, boxMax_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, settings_.mapSize, settings_.mapSize);
  const float one = 1.0f;
  glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
  glUseProgram(depthProgram.id());
  glProgramUniformMatrix4fv(depthProgram.id(), HAZE_LOC_VIEW_PROJ, 1, GL_FALSE, glm::value_ptr(viewProj_));
  gl::PassScope pass("sun shadow map");
  gl::Capability depthTest(GL_DEPTH_TEST, true), twoSided(GL_CULL_FACE, false);  // two-sided surfaces
  glDepthFunc(GL_LESS);
  // No polygon offset, unlike the beams' maps: an offset leaves a layer of air in front of
  // every surface that the map calls lit (a speckle of light on walls the sun never reaches,
  // from the march's last samples). Surfaces keep off their own depth by the normal offset in
  // sunIrradiance instead.
  venue.bind();
  venue.drawAll();
  haveMap_ = true;
  mapDirection_ = frame.sun.direction;
  return true;
}

void SunPass::bind(GLuint prog) const {
  glProgramUniform1i(prog, HAZE_LOC_SUN_ON, lit_ ? 1 : 0);
  if (!lit_) return;
  glProgramUniform3fv(prog, HAZE_LOC_SUN_DIRECTION, 1, glm::value_ptr(sun_.direction));
  glProgramUniform3fv(prog, HAZE_LOC_SUN_ILLUMINANCE, 1, glm::value_ptr(sun_.illuminance));
  glProgramUniformMatrix4fv(prog, HAZE_LOC_SUN_VIEW_PROJ, 1, GL_FALSE, glm::value_ptr(viewProj_));
  glProgramUniform3fv(prog, HAZE_LOC_SUN_BOX_MIN, 1, glm::value_ptr(boxMin_));
  glProgramUniform3fv(prog, HAZE_LOC_SUN_BOX_MAX, 1, glm::value_ptr(boxMax_));
  glBindTextureUnit(HAZE_UNIT_SUN_SHADOW, map_.id());
  if (pathField_) glBindTextureUnit(HAZE_UNIT_SUN_PATH, path_.id());
}

void SunPass::drawScatter(const FrameState& frame, float aspect, float frameJitter,
                          const DensityResources& density) const {
  if (!lit_ || !(frame.medium.scattering > 0.0f)) return;
  const GLuint prog = scatter_.id();
  glUseProgram(prog);
  setCameraUniforms(prog, frame.camera, aspect);
  glProgramUniform1i(prog, HAZE_LOC_PHASE, static_cast<int>(frame.medium.phase));
  glProgramUniform1f(prog, HAZE_LOC_PHASE_G, frame.medium.g);
  glProgramUniform4f(prog, HAZE_LOC_SUN_MARCH, frame.medium.scattering, frame.medium.extinction(),
                     static_cast<float>(settings_.steps), frameJitter);
  density.bind(prog);
  bind(prog);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace haze
