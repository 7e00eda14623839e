#include "renderer/gl/scope.h"
#include "renderer/beam_pass.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "renderer/beam_footprint.h"
#include "renderer/camera_uniforms.h"
#include "renderer/gl/program.h"
#include "renderer/shader_features.h"
#include "shaders/interface.h"

namespace haze {

Result<BeamPass> BeamPass::create(int width, int height, const BeamPassSettings& settings) {
  BeamPass p;
  p.settings_ = settings;
  p.settings_.planes = std::clamp(settings.planes, 1, 4096);
  p.settings_.scatterDivisor = std::clamp(settings.scatterDivisor, 1, 8);
  p.settings_.refineCurvature = std::max(settings.refineCurvature, 0.0f);
  p.settings_.frames = std::clamp(settings.frames, 1, 1024);
  p.settings_.lattice = std::clamp(settings.lattice, 0, 1024);
  if (p.settings_.lattice > 0) {  // the paper's form: plane instances, lattice points, no jitter
    p.settings_.fused = false;
    p.settings_.jitter = false;
  }

  std::vector<std::string> defines;
  if (p.settings_.fused) defines.push_back("FUSED");
  if (p.settings_.lattice > 0) defines.push_back("LATTICE");
  const gl::ProgramDesc planesDesc{.label = "virtual_planes", .vertex = "planes.vert.glsl",
                                   .fragment = "planes.frag.glsl", .defines = defines};
  auto planes = gl::buildProgram(planesDesc);
  if (!planes) return planes.error();
  auto composite = gl::buildProgram({.label = "scatter_composite", .vertex = "fullscreen.vert.glsl",
                                     .fragment = "composite.frag.glsl"});
  if (!composite) return composite.error();
  auto depth = gl::buildProgram({.label = "scatter_depth", .vertex = "fullscreen.vert.glsl",
                                 .fragment = "scatter_depth.frag.glsl"});
  if (!depth) return depth.error();
  auto mask = gl::buildProgram({.label = "refine_mask", .vertex = "fullscreen.vert.glsl",
                                .fragment = "refine_mask.frag.glsl"});
  if (!mask) return mask.error();
  defines.push_back("EARLY_STENCIL");
  const gl::ProgramDesc planesFineDesc{.label = "virtual_planes_refined", .vertex = "planes.vert.glsl",
                                       .fragment = "planes.frag.glsl", .defines = defines};
  auto planesFine = gl::buildProgram(planesFineDesc);
  if (!planesFine) return planesFine.error();
  p.planes_ = std::move(*planes);
  p.planesFine_ = std::move(*planesFine);
  p.planesStatic_ = gl::ProgramVariants(planesDesc);
  p.planesFineStatic_ = gl::ProgramVariants(planesFineDesc);
  p.composite_ = std::move(*composite);
  p.scatterDepth_ = std::move(*depth);
  p.refineMask_ = std::move(*mask);

  p.scatterFbo_ = gl::Framebuffer("scatter_fbo");
  p.lowDepthFbo_ = gl::Framebuffer("scatter_depth_fbo");
  p.fineFbo_ = gl::Framebuffer("scatter_fine_fbo");
  p.maskFbo_ = gl::Framebuffer("refine_mask_fbo");
  p.vao_ = gl::VertexArray("planes_vao");
  p.scattered_ = gl::SamplesQuery("scattering_fragments");
  p.resize(width, height);
  return p;
}

void BeamPass::resize(int width, int height) {
  if (scatter_ && width == width_ && height == height_) return;
  width_ = width;
  height_ = height;
  lowW_ = std::max(1, (width + settings_.scatterDivisor - 1) / settings_.scatterDivisor);
  lowH_ = std::max(1, (height + settings_.scatterDivisor - 1) / settings_.scatterDivisor);
  scatter_ = gl::Texture(GL_TEXTURE_2D, "scatter");
  // With refinement the buffer has a mip chain: its last level is the frame's mean in-scattering,
  // the scale that tells detail worth refining from the faint tails of beams.
  scatterLevels_ = refining() ? 1 + static_cast<int>(std::floor(std::log2(std::max(lowW_, lowH_)))) : 1;
  glTextureStorage2D(scatter_.id(), scatterLevels_, GL_RGBA32F, lowW_, lowH_);
  glTextureParameteri(scatter_.id(), GL_TEXTURE_MIN_FILTER, scatterLevels_ > 1 ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST);
  glTextureParameteri(scatter_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glNamedFramebufferTexture(scatterFbo_.id(), GL_COLOR_ATTACHMENT0, scatter_.id(), 0);
  lowDepth_ = gl::Texture(GL_TEXTURE_2D, "scatter_depth");
  glTextureStorage2D(lowDepth_.id(), 1, GL_R32F, lowW_, lowH_);
  glTextureParameteri(lowDepth_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(lowDepth_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glNamedFramebufferTexture(lowDepthFbo_.id(), GL_COLOR_ATTACHMENT0, lowDepth_.id(), 0);
  if (refining()) {
    fine_ = gl::Texture(GL_TEXTURE_2D, "scatter_fine");
    glTextureStorage2D(fine_.id(), 1, GL_RGBA32F, width, height);
    mask_ = gl::Texture(GL_TEXTURE_2D, "refine_mask");
    glTextureStorage2D(mask_.id(), 1, GL_R8, width, height);
    for (GLuint t : {fine_.id(), mask_.id()}) {
      glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    stencil_ = gl::Renderbuffer("refine_stencil");
    glNamedRenderbufferStorage(stencil_.id(), GL_STENCIL_INDEX8, width, height);
    glNamedFramebufferTexture(fineFbo_.id(), GL_COLOR_ATTACHMENT0, fine_.id(), 0);
    glNamedFramebufferRenderbuffer(fineFbo_.id(), GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, stencil_.id());
    glNamedFramebufferTexture(maskFbo_.id(), GL_COLOR_ATTACHMENT0, mask_.id(), 0);
    glNamedFramebufferRenderbuffer(maskFbo_.id(), GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, stencil_.id());
  }
  accumulated_ = 0;  // what was accumulated was for the old size
}

uint64_t BeamPass::render(const FrameState& frame, const BeamResources& beams, const DensityResources& density,
                          GLuint sceneDepth,
                          GLuint radianceFbo, bool accumulate, const SunPass* sun) {
  const MediumState& med = frame.medium;
  beamsDrawn_ = 0;
  if (sun && !sun->lit()) sun = nullptr;
  if (med.scattering <= 0.0f || (frame.beams.empty() && !sun)) return 0;
  const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
  glBindTextureUnit(HAZE_UNIT_SCENE_DEPTH, sceneDepth);
  glBindVertexArray(vao_.id());
  // The passes below switch blending and the stencil test as they go; these put back at the end
  // what the caller had.
  gl::Capability depthTest(GL_DEPTH_TEST, false), twoSided(GL_CULL_FACE, false), blend(GL_BLEND, false),
      stencil(GL_STENCIL_TEST, false);

  if (settings_.scatterDivisor > 1) {  // the scene depth at each low-resolution texel
    glBindFramebuffer(GL_FRAMEBUFFER, lowDepthFbo_.id());
    glViewport(0, 0, lowW_, lowH_);
    glDisable(GL_BLEND);
    glUseProgram(scatterDepth_.id());
    setCameraUniforms(scatterDepth_.id(), frame.camera, aspect);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }

  glBindFramebuffer(GL_FRAMEBUFFER, scatterFbo_.id());
  glViewport(0, 0, lowW_, lowH_);
  if (!accumulate) {
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(scatterFbo_.id(), GL_COLOR, 0, zero);
    accumulated_ = 0;
  }
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glBlendEquation(GL_FUNC_ADD);
  // The refinement's program is the same shader with early stencil tests: without them
  // llvmpipe shades every fragment of the footprint before the stencil rejects it.
  // The programs with this frame's switches compiled in, or (off, or one that does not build)
  // the ones that read them from uniforms.
  GLuint planesProg = planes_.id(), fineProg = planesFine_.id();
  if (settings_.staticFeatures) {
    const std::vector<std::string> features =
        ShaderFeatures{.densityField = density.on(), .softShadows = beams.softShadows(), .phase = static_cast<int>(med.phase)}
            .defines();
    if (GLuint p = planesStatic_.get(features)) planesProg = p;
    if (refining())
      if (GLuint p = planesFineStatic_.get(features)) fineProg = p;
  }
  for (GLuint prog : {planesProg, refining() ? fineProg : 0u}) {
    if (prog == 0) continue;
    setCameraUniforms(prog, frame.camera, aspect);
    glProgramUniform1f(prog, HAZE_LOC_SCATTER_SIGMA_S, med.scattering);
    glProgramUniform1f(prog, HAZE_LOC_SCATTER_SIGMA_T, med.extinction());
    glProgramUniform1i(prog, HAZE_LOC_SCATTER_JITTER, settings_.jitter ? 1 : 0);
    glProgramUniform1i(prog, HAZE_LOC_SCATTER_PLANES, settings_.planes);
    glProgramUniform1i(prog, HAZE_LOC_SCATTER_MIN_SAMPLES, settings_.minSamplesPerChord);
    glProgramUniform2i(prog, HAZE_LOC_SCATTER_LATTICE, settings_.lattice, settings_.lattice);
    glProgramUniform1i(prog, HAZE_LOC_PHASE, static_cast<int>(med.phase));  // Phase's values are HAZE_PHASE_*
    glProgramUniform1f(prog, HAZE_LOC_PHASE_G, med.g);
    density.bind(prog);
    beams.bindSoftShadows(prog);
  }
  beams.bind();

  // Each cone only as far as it can light anything (its shadow map's farthest surface).
  std::vector<BeamFootprint> footprints(frame.beams.size());
  for (size_t i = 0; i < frame.beams.size(); ++i) {
    const BeamOptics& o = frame.beams[i].optics;
    if (o.dimmer <= 0.0f || o.color == glm::vec3(0.0f)) continue;  // dark: adds nothing anywhere
    if (!beams.drawn(static_cast<int>(i))) continue;  // left out by a GL limit (the renderer warns)
    footprints[i] = beamFootprint(frame.beams[i], frame.camera, aspect, beams.reachM(static_cast<int>(i)));
    beamsDrawn_ += footprints[i].visible ? 1 : 0;
  }

  if (refining() && !accumulate) {
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(fineFbo_.id(), GL_COLOR, 0, zero);
  }
  uint64_t fragments = 0;
  glBeginQuery(GL_SAMPLES_PASSED, scattered_.id());
  for (int f = 0; f < settings_.frames; ++f) {
    // Golden-ratio steps give well-spread offsets for any number of accumulated frames.
    const float jitter = std::fmod(static_cast<float>(accumulated_) * 0.6180339887f, 1.0f);
    glBindFramebuffer(GL_FRAMEBUFFER, scatterFbo_.id());
    glViewport(0, 0, lowW_, lowH_);
    fragments += drawBeams(planesProg, jitter, frame, footprints, lowW_, lowH_);
    if (sun) sun->drawScatter(frame, aspect, jitter, density);
    if (refining()) {
      // The mask follows the first frame of an accumulation and is kept for the rest, so that
      // every refined pixel averages the same frames.
      if (accumulated_ == 0) markRefinedPixels();
      glBindFramebuffer(GL_FRAMEBUFFER, fineFbo_.id());
      glViewport(0, 0, width_, height_);
      glEnable(GL_STENCIL_TEST);
      glStencilFunc(GL_EQUAL, 1, 0xFF);
      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
      drawBeams(fineProg, jitter, frame, footprints, width_, height_);
      if (sun) sun->drawScatter(frame, aspect, jitter, density);
      glDisable(GL_STENCIL_TEST);
    }
    ++accumulated_;
  }
  glEndQuery(GL_SAMPLES_PASSED);

  // Composite onto the radiance target, averaging the accumulated frames.
  glBindFramebuffer(GL_FRAMEBUFFER, radianceFbo);
  glViewport(0, 0, width_, height_);
  glUseProgram(composite_.id());
  setCameraUniforms(composite_.id(), frame.camera, aspect);
  glProgramUniform1f(composite_.id(), HAZE_LOC_COMPOSITE_SCALE, 1.0f / static_cast<float>(accumulated_));
  glProgramUniform1i(composite_.id(), HAZE_LOC_COMPOSITE_UPSAMPLE, settings_.scatterDivisor > 1 ? 1 : 0);
  glBindTextureUnit(HAZE_UNIT_SCATTER, scatter_.id());
  glBindTextureUnit(HAZE_UNIT_SCATTER_DEPTH, lowDepth_.id());
  glProgramUniform1i(composite_.id(), HAZE_LOC_COMPOSITE_REFINE, refining() ? 1 : 0);
  if (refining()) {
    glBindTextureUnit(HAZE_UNIT_SCATTER_FINE, fine_.id());
    glBindTextureUnit(HAZE_UNIT_REFINE_MASK, mask_.id());
  }
  glDrawArrays(GL_TRIANGLES, 0, 3);
  return fragments;
}

// One jittered frame of every visible beam into the bound target of targetW x targetH pixels;
// returns the plane fragments rasterised (an estimate from the footprints, for the bench).
uint64_t BeamPass::drawBeams(GLuint prog, float frameJitter, const FrameState& frame,
                             const std::vector<BeamFootprint>& footprints, int targetW, int targetH) {
  glUseProgram(prog);
  glProgramUniform1f(prog, HAZE_LOC_SCATTER_FRAME_JITTER, frameJitter);
  glProgramUniform2f(prog, HAZE_LOC_SCATTER_TARGET_SIZE, static_cast<float>(targetW), static_cast<float>(targetH));
  uint64_t fragments = 0;
  for (size_t i = 0; i < frame.beams.size(); ++i) {
    const BeamFootprint& fp = footprints[i];
    if (!fp.visible) continue;
    const float dz = (fp.zFar - fp.zNear) / static_cast<float>(settings_.planes);
    glProgramUniform4fv(prog, HAZE_LOC_PLANES_RECT_NDC, 1, glm::value_ptr(fp.rectNdc));
    if (settings_.lattice == 0)
      glProgramUniform2fv(prog, HAZE_LOC_PLANES_POLYGON_NDC, fp.vertexCount, glm::value_ptr(fp.polygonNdc[0]));
    glProgramUniform2f(prog, HAZE_LOC_SCATTER_DEPTH_RANGE, fp.zNear, dz);
    glProgramUniform1i(prog, HAZE_LOC_SCATTER_BEAM, static_cast<int>(i));
    const int instances = settings_.fused ? 1 : settings_.planes;
    double px = 0.0;
    if (settings_.lattice > 0) {  // the paper's lattice spans the bounding rectangle
      glDrawArraysInstanced(GL_TRIANGLES, 0, 6 * settings_.lattice * settings_.lattice, instances);
      px = (fp.rectNdc.z - fp.rectNdc.x) * 0.5 * targetW * (fp.rectNdc.w - fp.rectNdc.y) * 0.5 * targetH;
    } else {
      glDrawArraysInstanced(GL_TRIANGLE_FAN, 0, fp.vertexCount, instances);
      px = fp.areaNdc() * 0.25 * targetW * targetH;
    }
    fragments += static_cast<uint64_t>(px) * static_cast<uint64_t>(instances);
  }
  return fragments;
}

// Stencil 1 (and mask 1) on the pixels refine_mask.frag.glsl keeps.
void BeamPass::markRefinedPixels() {
  glBindFramebuffer(GL_FRAMEBUFFER, maskFbo_.id());
  glViewport(0, 0, width_, height_);
  const float zero[4] = {0, 0, 0, 0};
  glStencilMask(0xFF);
  glClearNamedFramebufferfv(maskFbo_.id(), GL_COLOR, 0, zero);
  const GLint zeroStencil = 0;
  glClearNamedFramebufferiv(maskFbo_.id(), GL_STENCIL, 0, &zeroStencil);
  glDisable(GL_BLEND);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glUseProgram(refineMask_.id());
  glProgramUniform1f(refineMask_.id(), HAZE_LOC_REFINE_CONTRAST, settings_.refineCurvature);
  glProgramUniform1f(refineMask_.id(), HAZE_LOC_REFINE_FLOOR, settings_.refineFloor);
  glGenerateTextureMipmap(scatter_.id());
  glBindTextureUnit(HAZE_UNIT_SCATTER, scatter_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_BLEND);
}

uint64_t BeamPass::refinedPixels() const {
  if (!refining() || !mask_) return 0;
  std::vector<uint8_t> m(static_cast<size_t>(width_) * static_cast<size_t>(height_));
  glGetTextureImage(mask_.id(), 0, GL_RED, GL_UNSIGNED_BYTE, static_cast<GLsizei>(m.size()), m.data());
  uint64_t n = 0;
  for (uint8_t v : m) n += v > 127 ? 1 : 0;
  return n;
}

uint64_t BeamPass::scatteringFragments() const {
  if (!scattered_) return 0;
  GLuint64 n = 0;
  glGetQueryObjectui64v(scattered_.id(), GL_QUERY_RESULT, &n);
  return n;
}

}  // namespace haze
