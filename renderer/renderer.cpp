#include "renderer/renderer.h"

#include <cassert>
#include <chrono>
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include <glm/gtc/type_ptr.hpp>

#include "renderer/beam_pass.h"
#include "renderer/camera_uniforms.h"
#include "renderer/beam_resources.h"
#include "renderer/density_resources.h"
#include "renderer/gl/scope.h"
#include "renderer/gl/program.h"
#include "renderer/shader_features.h"
#include "renderer/gpu_bodies.h"
#include "renderer/gpu_venue.h"
#include "renderer/light_tiles.h"
#include "renderer/sun_pass.h"
#include "renderer/particle_pass.h"
#include "shows/scene/camera_basis.h"
#include "shaders/interface.h"

namespace haze {
namespace {

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

Status checkSize(int width, int height) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    return Error{"", "", "image size must be between 1x1 and 16384x16384"};
  return Ok{};
}

// "fixtures 3, 7-9 and 12": ids in runs, for a warning that names them all in one line.
std::string fixtureList(std::vector<int> ids) {
  std::sort(ids.begin(), ids.end());
  std::vector<std::string> runs;
  for (size_t i = 0; i < ids.size();) {
    size_t j = i;
    while (j + 1 < ids.size() && ids[j + 1] == ids[j] + 1) ++j;
    runs.push_back(j == i ? std::to_string(ids[i]) : std::to_string(ids[i]) + "-" + std::to_string(ids[j]));
    i = j + 1;
  }
  std::string out = ids.size() == 1 && runs.size() == 1 && runs[0].find('-') == std::string::npos ? "fixture " : "fixtures ";
  for (size_t i = 0; i < runs.size(); ++i)
    out += (i == 0 ? "" : i + 1 == runs.size() ? " and " : ", ") + runs[i];
  return out;
}

}  // namespace

struct Renderer::Impl {
  GpuVenue venue;
  GpuBodies bodies;
  BeamResources beams;
  DensityResources density;
  gl::Program shadowProgram, gbufferProgram, surfaceProgram, lensProgram, postProgram, bloomPostProgram;
  gl::ProgramVariants surfaceStatic;  // surfaceProgram with the frame's switches compiled in (ShaderFeatures)
  gl::Texture radiance, depth, display;
  // The surfaces' attributes per pixel (gbuffer.frag.glsl), lit once per pixel by surface.frag.glsl.
  gl::Texture gbuffer;
  gl::Framebuffer gbufferFbo{"gbuffer_fbo"};
  gl::Sampler mipSampler{"radiance_mips"};  // for bloom: trilinear over the radiance's mip levels
  // For an image drawn larger than it was rendered (the GUI's reduced drafts): bilinear, not blocks.
  gl::Sampler stretchSampler{"radiance_stretched"};
  gl::Framebuffer sceneFbo{"scene_fbo"}, displayFbo{"display_fbo"};
  // The radiance target without its depth, for passes that read the scene depth as a texture.
  gl::Framebuffer radianceOnlyFbo{"radiance_only_fbo"};
  BeamPass beamPass;
  SunPass sun;
  ParticlePass particles;
  LightTiles tiles;
  gl::VertexArray emptyVao{"fullscreen_vao"};
  // Shadow maps, surfaces, beams, particles; used only with RenderSettings::timePasses.
  gl::TimerQuery timers[4] = {gl::TimerQuery{"shadow_maps_time"}, gl::TimerQuery{"surfaces_time"},
                              gl::TimerQuery{"beams_time"}, gl::TimerQuery{"particles_time"}};

  Impl(const Venue& v, const RenderSettings& s)
      : venue(v, s.cullVenueChunks),
        beams(BeamResourceSettings{s.lightMapSize, s.shadowMapSize, s.shadowTexelBudget, s.shadowMinPyramid,
                                   s.mapWorkBudgetMs}) {}

  // (Re)makes the targets whose size is the image's; nothing else depends on it.
  Status allocateTargets(int w, int h);

  // The passes of a frame, in order (Renderer::render).
  struct View {
    int width = 0, height = 0;
    float aspect = 1.0f, sigmaT = 0.0f;
    glm::mat4 viewProj{1.0f};
  };
  View view(const FrameState& frame, const RenderSettings& settings) const;
  void updateMaps(const FrameState& frame, PassTimes& times, std::vector<std::string>& warnings);
  void clearScene(const FrameState& frame, const View& v);
  void drawSurfaceAttributes(const FrameState& frame, const View& v, bool cullBodies, PassTimes& times);
  void lightSurfaces(const FrameState& frame, const View& v, bool tiledSurfaces, bool staticFeatures);
  void drawLenses(const FrameState& frame, const View& v);
  void drawParticles(const FrameState& frame, const View& v, PassTimes& times, std::vector<std::string>& warnings);
  void collectTimes(const FrameState& frame, const RenderSettings& settings, PassTimes& times);
};

Status Renderer::Impl::allocateTargets(int w, int h) {
  radiance = gl::Texture(GL_TEXTURE_2D, "radiance");
  // Mip levels for bloom only (made on demand); everything else uses level 0.
  int levels = 1;
  while ((std::max(w, h) >> levels) > 0) ++levels;
  glTextureStorage2D(radiance.id(), levels, GL_RGBA32F, w, h);
  glTextureParameteri(radiance.id(), GL_TEXTURE_MAX_LEVEL, levels - 1);
  glTextureParameteri(radiance.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(radiance.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  depth = gl::Texture(GL_TEXTURE_2D, "scene_depth");
  glTextureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT32F, w, h);
  glTextureParameteri(depth.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(depth.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glNamedFramebufferTexture(radianceOnlyFbo.id(), GL_COLOR_ATTACHMENT0, radiance.id(), 0);
  glNamedFramebufferTexture(sceneFbo.id(), GL_COLOR_ATTACHMENT0, radiance.id(), 0);
  glNamedFramebufferTexture(sceneFbo.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
  gbuffer = gl::Texture(GL_TEXTURE_2D, "gbuffer");
  glTextureStorage2D(gbuffer.id(), 1, GL_RGBA32UI, w, h);
  glTextureParameteri(gbuffer.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // an integer texture is complete only so
  glTextureParameteri(gbuffer.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glNamedFramebufferTexture(gbufferFbo.id(), GL_COLOR_ATTACHMENT0, gbuffer.id(), 0);
  glNamedFramebufferTexture(gbufferFbo.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
  display = gl::Texture(GL_TEXTURE_2D, "display");
  glTextureStorage2D(display.id(), 1, GL_RGBA8, w, h);
  glNamedFramebufferTexture(displayFbo.id(), GL_COLOR_ATTACHMENT0, display.id(), 0);
  if (glCheckNamedFramebufferStatus(sceneFbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE ||
      glCheckNamedFramebufferStatus(displayFbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE ||
      glCheckNamedFramebufferStatus(gbufferFbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    return Error{"", "", "the GL driver cannot render to RGBA32F, RGBA16F and DEPTH32F targets"};
  beamPass.resize(w, h);
  tiles.resize(w, h);
  return Ok{};
}

Renderer::Renderer(std::unique_ptr<Impl> impl, const RenderSettings& settings)
    : impl_(std::move(impl)), settings_(settings) {}
Renderer::~Renderer() = default;

Result<std::unique_ptr<Renderer>> Renderer::create(const Venue& venue, const RenderSettings& settings) {
  if (Status size = checkSize(settings.width, settings.height); !size) return size.error();
  auto impl = std::make_unique<Impl>(venue, settings);
  auto shadow = gl::buildProgram({.label = "shadow_depth", .vertex = "venue.vert.glsl"});
  if (!shadow) return shadow.error();
  auto gbuffer = gl::buildProgram({.label = "gbuffer", .vertex = "venue.vert.glsl", .fragment = "gbuffer.frag.glsl"});
  if (!gbuffer) return gbuffer.error();
  impl->gbufferProgram = std::move(*gbuffer);
  const gl::ProgramDesc surfaceDesc{.label = "surface", .vertex = "fullscreen.vert.glsl", .fragment = "surface.frag.glsl"};
  auto surface = gl::buildProgram(surfaceDesc);
  impl->surfaceStatic = gl::ProgramVariants(surfaceDesc);
  if (!surface) return surface.error();
  auto lens = gl::buildProgram({.label = "lens", .vertex = "lens.vert.glsl", .fragment = "lens.frag.glsl"});
  if (!lens) return lens.error();
  impl->lensProgram = std::move(*lens);
  auto post = gl::buildProgram({.label = "post", .vertex = "fullscreen.vert.glsl", .fragment = "post.frag.glsl"});
  if (!post) return post.error();
  auto bloomPost = gl::buildProgram(
      {.label = "post_bloom", .vertex = "fullscreen.vert.glsl", .fragment = "post.frag.glsl", .defines = {"BLOOM"}});
  if (!bloomPost) return bloomPost.error();
  impl->bloomPostProgram = std::move(*bloomPost);
  impl->shadowProgram = std::move(*shadow);
  impl->surfaceProgram = std::move(*surface);
  impl->postProgram = std::move(*post);
  auto pass = BeamPass::create(settings.width, settings.height,
                               {.planes = settings.planes, .scatterDivisor = settings.scatterDivisor,
                                .refineCurvature = settings.refineCurvature,
                                .refineFloor = settings.refineFloor, .frames = settings.frames, .jitter = settings.jitter,
                                .fused = settings.fusedPlanes, .minSamplesPerChord = settings.minSamplesPerChord,
                                .lattice = settings.lattice, .staticFeatures = settings.staticFeatures});
  if (!pass) return pass.error();
  impl->beamPass = std::move(*pass);
  auto sun = SunPass::create({.mapSize = settings.sunMapSize, .steps = settings.sunSteps});
  if (!sun) return sun.error();
  impl->sun = std::move(*sun);
  auto particles = ParticlePass::create();
  if (!particles) return particles.error();
  impl->particles = std::move(*particles);
  auto tiles = LightTiles::create(settings.width, settings.height);
  if (!tiles) return tiles.error();
  impl->tiles = std::move(*tiles);

  glSamplerParameteri(impl->mipSampler.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  glSamplerParameteri(impl->mipSampler.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(impl->mipSampler.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(impl->mipSampler.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(impl->stretchSampler.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(impl->stretchSampler.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(impl->stretchSampler.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(impl->stretchSampler.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  if (Status targets = impl->allocateTargets(settings.width, settings.height); !targets) return targets.error();
  return std::unique_ptr<Renderer>(new Renderer(std::move(impl), settings));
}

Status Renderer::resize(int width, int height) {
  if (Status size = checkSize(width, height); !size) return size;
  if (width == settings_.width && height == settings_.height) return Ok{};
  if (Status targets = impl_->allocateTargets(width, height); !targets) return targets;
  settings_.width = width;
  settings_.height = height;
  return Ok{};
}

void Renderer::setMapWorkBudgetMs(double ms) {
  settings_.mapWorkBudgetMs = ms;
  impl_->beams.setMapWorkBudgetMs(ms);
}

void Renderer::render(const FrameState& frame, bool accumulate) {
  Impl& m = *impl_;
  times_ = {};
  warnings_.clear();
  // Timer queries rather than glFinish: nothing waits for the GL until the results are read at
  // the end, and not at all unless timing was asked for.
  const auto timer = [&](int pass) { return settings_.timePasses ? m.timers[pass].id() : 0u; };
  const Impl::View view = m.view(frame, settings_);
  {
    gl::PassScope pass("shadow and light maps", timer(0));
    m.updateMaps(frame, times_, warnings_);
  }
  {
    gl::PassScope pass("surfaces", timer(1));
    m.density.update(frame, view.aspect, m.beams);
    m.clearScene(frame, view);
    m.drawSurfaceAttributes(frame, view, settings_.cullBodies, times_);
    m.lightSurfaces(frame, view, settings_.tiledSurfaces, settings_.staticFeatures);
    m.drawLenses(frame, view);
  }
  {
    gl::PassScope pass("beams", timer(2));
    times_.planeFragments =
        m.beamPass.render(frame, m.beams, m.density, m.depth.id(), m.radianceOnlyFbo.id(), accumulate, &m.sun);
  }
  // Visible dust (docs/rendering.md, "Particles"): a display option added after the
  // radiometric composite, so with it off the image is exactly the radiometric one.
  if (frame.particles.settings.enabled) {
    gl::PassScope pass("particles", timer(3));
    m.drawParticles(frame, view, times_, warnings_);
  }
  m.collectTimes(frame, settings_, times_);
}

Renderer::Impl::View Renderer::Impl::view(const FrameState& frame, const RenderSettings& settings) const {
  View v{.width = settings.width, .height = settings.height};
  v.aspect = static_cast<float>(v.width) / static_cast<float>(v.height);
  v.viewProj = cameraViewProjection(frame.camera, v.aspect);
  v.sigmaT = frame.medium.extinction();
  return v;
}

// Bodies first: the beams' shadow maps draw other fixtures' bodies.
void Renderer::Impl::updateMaps(const FrameState& frame, PassTimes& times, std::vector<std::string>& warnings) {
  bodies.update(frame.bodies, frame.bodyMeshes);
  BeamUpdateStats stats = beams.update(frame, venue, bodies, shadowProgram);
  times.sunMapRendered = sun.update(frame, venue, shadowProgram);
  times.shadowMapsRendered = stats.shadowMapsRendered;
  times.mapsPending = stats.mapsPending;
  times.lightMapsBaked = stats.lightMapsBaked;
  times.shadowMapSize = stats.shadowMapSize;
  times.lightMapLayers = stats.lightMapLayers;
  if (!stats.notDrawn.empty())
    warnings.push_back(fixtureList(std::move(stats.notDrawn)) + " not drawn (" +
                       std::to_string(frame.beams.size() - static_cast<size_t>(beams.drawnCount())) + " of " +
                       std::to_string(frame.beams.size()) + " beams): " + stats.notDrawnReason);
}

// Where no surface is hit the ray ends at the camera's far distance (docs/physics.md); through a
// density field, attenuated by its path along the view axis (docs/rendering.md, "Density").
void Renderer::Impl::clearScene(const FrameState& frame, const View& v) {
  glBindFramebuffer(GL_FRAMEBUFFER, sceneFbo.id());
  glViewport(0, 0, v.width, v.height);
  const float backgroundPath = density.on() ? density.backgroundPath() : frame.camera.farM;
  const glm::vec4 background(frame.medium.background * std::exp(-v.sigmaT * backgroundPath), 1.0f);
  glClearNamedFramebufferfv(sceneFbo.id(), GL_COLOR, 0, glm::value_ptr(background));
  const float one = 1.0f;
  gl::DepthMask write(true);  // a depth clear honours the mask
  glClearNamedFramebufferfv(sceneFbo.id(), GL_DEPTH, 0, &one);
}

// The surfaces' attributes, depth-tested, into the G-buffer: the venue, then the fixtures' bodies.
void Renderer::Impl::drawSurfaceAttributes(const FrameState& frame, const View& v, bool cullBodies, PassTimes& times) {
  gl::PassScope pass("surface attributes");
  gl::Capability depthTest(GL_DEPTH_TEST, true), twoSided(GL_CULL_FACE, false), blend(GL_BLEND, false);
  gl::DepthMask write(true);
  glDepthFunc(GL_LESS);
  glBindFramebuffer(GL_FRAMEBUFFER, gbufferFbo.id());
  const GLuint gprog = gbufferProgram.id();
  glUseProgram(gprog);
  glProgramUniformMatrix4fv(gprog, HAZE_LOC_VIEW_PROJ, 1, GL_FALSE, glm::value_ptr(v.viewProj));
  venue.bind();
  for (const GpuVenue::Draw& d : venue.draws()) {
    const GpuVenue::GpuMaterial& mat = venue.materials()[static_cast<size_t>(d.material)];
    glProgramUniform4fv(gprog, HAZE_LOC_SURFACE_BASE_COLOR, 1, glm::value_ptr(mat.baseColor));
    glProgramUniform3fv(gprog, HAZE_LOC_SURFACE_EMISSIVE, 1, glm::value_ptr(mat.emissive));
    glProgramUniform1i(gprog, HAZE_LOC_SURFACE_HAS_BASE_TEXTURE, mat.baseColorTexture >= 0);
    glProgramUniform1i(gprog, HAZE_LOC_SURFACE_HAS_EMISSIVE_TEXTURE, mat.emissiveTexture >= 0);
    if (mat.baseColorTexture >= 0) glBindTextureUnit(HAZE_UNIT_BASE_TEXTURE, venue.texture(mat.baseColorTexture).id());
    if (mat.emissiveTexture >= 0)
      glBindTextureUnit(HAZE_UNIT_EMISSIVE_TEXTURE, venue.texture(mat.emissiveTexture).id());
    venue.draw(d);
  }
  const GpuBodies::Camera bodyCamera{v.viewProj, frame.camera.position};
  const GpuBodies::Camera* cull = cullBodies ? &bodyCamera : nullptr;
  if (!bodies.empty() || bodies.hasMeshes()) {
    const glm::vec3 black(0.0f);
    glProgramUniform1i(gprog, HAZE_LOC_SURFACE_HAS_BASE_TEXTURE, 0);
    glProgramUniform1i(gprog, HAZE_LOC_SURFACE_HAS_EMISSIVE_TEXTURE, 0);
    glProgramUniform3fv(gprog, HAZE_LOC_SURFACE_EMISSIVE, 1, glm::value_ptr(black));
  }
  if (!bodies.empty()) {
    bodies.bind();
    for (const GpuBodies::Draw& d : bodies.draws()) {
      const glm::vec4 albedo(d.albedo, 1.0f);
      glProgramUniform4fv(gprog, HAZE_LOC_SURFACE_BASE_COLOR, 1, glm::value_ptr(albedo));
      bodies.draw(d);
    }
  }
  if (bodies.hasMeshes()) bodies.drawMeshes(gprog, HAZE_LOC_SURFACE_BASE_COLOR, cull);
  times.bodyMeshesDrawn = cull ? bodies.meshesDrawn() : static_cast<int>(frame.bodyMeshes.size());
}

// The lighting once per pixel over the G-buffer (a full-screen triangle), each pixel's beams
// from its screen tile's list when the surfaces are tiled.
void Renderer::Impl::lightSurfaces(const FrameState& frame, const View& v, bool tiledSurfaces, bool staticFeatures) {
  gl::PassScope pass("surface lighting");
  gl::Capability depthTest(GL_DEPTH_TEST, false), blend(GL_BLEND, false);
  beams.bind();
  const bool tiled = tiledSurfaces && beams.count() > 0;
  if (tiled) {
    glBindTextureUnit(HAZE_UNIT_SCENE_DEPTH, depth.id());
    tiles.update(frame.camera, beams.count());
    tiles.bind();
  }
  glBindFramebuffer(GL_FRAMEBUFFER, radianceOnlyFbo.id());
  GLuint prog = surfaceProgram.id();
  if (staticFeatures) {
    const ShaderFeatures features{.densityField = density.on(), .sun = sun.lit(), .softShadows = beams.softShadows()};
    if (GLuint p = surfaceStatic.get(features.defines())) prog = p;
  }
  glUseProgram(prog);
  setCameraUniforms(prog, frame.camera, v.aspect);
  glProgramUniform1f(prog, HAZE_LOC_SURFACE_SIGMA_T, v.sigmaT);
  glProgramUniform3fv(prog, HAZE_LOC_SURFACE_AMBIENT, 1, glm::value_ptr(frame.medium.ambient));
  glProgramUniform1i(prog, HAZE_LOC_SURFACE_BEAM_COUNT, beams.count());
  glProgramUniform1i(prog, HAZE_LOC_SURFACE_TILE_COLUMNS, tiled ? tiles.columns() : 0);
  glProgramUniform1i(prog, HAZE_LOC_SURFACE_MASK_WORDS, tiles.maskWords());
  beams.bindSoftShadows(prog);
  density.bind(prog);
  sun.bind(prog);
  glBindTextureUnit(HAZE_UNIT_GBUFFER, gbuffer.id());
  glBindTextureUnit(HAZE_UNIT_SCENE_DEPTH, depth.id());
  glBindVertexArray(emptyVao.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

// The lens discs, after the venue so that they hide what lies behind them and their depth ends
// the beam pass's eye rays there (docs/rendering.md, "Lenses"). A few pixels each.
void Renderer::Impl::drawLenses(const FrameState& frame, const View& v) {
  glBindFramebuffer(GL_FRAMEBUFFER, sceneFbo.id());
  if (beams.count() == 0) return;
  gl::PassScope pass("lenses");
  gl::Capability depthTest(GL_DEPTH_TEST, true), blend(GL_BLEND, false);
  gl::DepthMask write(true);
  glDepthFunc(GL_LESS);
  const GLuint lensProg = lensProgram.id();
  glUseProgram(lensProg);
  glProgramUniformMatrix4fv(lensProg, HAZE_LOC_LENS_VIEW_PROJ, 1, GL_FALSE, glm::value_ptr(v.viewProj));
  glProgramUniform1f(lensProg, HAZE_LOC_LENS_SIGMA_T, v.sigmaT);
  glProgramUniform3fv(lensProg, HAZE_LOC_CAMERA_EYE, 1, glm::value_ptr(frame.camera.position));
  density.bind(lensProg);
  glBindVertexArray(emptyVao.id());
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, beams.count());
}

void Renderer::Impl::drawParticles(const FrameState& frame, const View& v, PassTimes& times,
                                   std::vector<std::string>& warnings) {
  glBindFramebuffer(GL_FRAMEBUFFER, sceneFbo.id());
  glViewport(0, 0, v.width, v.height);
  const ParticleStats ps = particles.render(frame, beams, density, v.viewProj, v.aspect, v.width, v.height,
                                            venue.boundsMin(), venue.boundsMax());
  times.particlesDrawn = ps.drawn;
  times.particlesWanted = ps.wanted;
  times.particlesGenerateMs = ps.generateMs;
  if (ps.wanted > ps.drawn)
    warnings.push_back("particles: " + std::to_string(ps.drawn) + " of " + std::to_string(ps.wanted) +
                       " drawn, the limit of " + std::to_string(frame.particles.limit) +
                       " per frame (thinned evenly; lower the particle density)");
}

// The passes' counts, and with timing on their GL times (this waits for the GL).
void Renderer::Impl::collectTimes(const FrameState& frame, const RenderSettings& settings, PassTimes& times) {
  times.accumulatedFrames = beamPass.accumulatedFrames();
  times.beamsDrawn = beamPass.beamsDrawn();
  if (!settings.timePasses) return;
  times.scatteringFragments = beamPass.scatteringFragments();
  times.refinedPixels = beamPass.refinedPixels();
  if (settings.tiledSurfaces && beams.count() > 0) times.beamsPerTile = tiles.meanBeamsPerTile();
  double* ms[4] = {&times.shadowMapsMs, &times.surfacesMs, &times.beamsMs, &times.particlesMs};
  for (int i = 0; i < (frame.particles.settings.enabled ? 4 : 3); ++i) {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(timers[i].id(), GL_QUERY_RESULT, &ns);
    *ms[i] = static_cast<double>(ns) * 1e-6;
  }
}

ImageRGB Renderer::readRadiance() const {
  const int w = settings_.width, h = settings_.height;
  std::vector<glm::vec4> rgba(static_cast<size_t>(w) * h);
  glGetTextureImage(impl_->radiance.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * sizeof(glm::vec4)),
                    rgba.data());
  ImageRGB img;
  img.width = w;
  img.height = h;
  img.pixels.resize(rgba.size());
  for (int y = 0; y < h; ++y)  // GL's row 0 is the bottom
    for (int x = 0; x < w; ++x) img.at(x, y) = glm::vec3(rgba[static_cast<size_t>(h - 1 - y) * w + x]);
  return img;
}

void Renderer::setRadiance(const ImageRGB& image) {
  const int w = settings_.width, h = settings_.height;
  assert(image.width == w && image.height == h && "setRadiance needs an image of the renderer's size");
  std::vector<glm::vec4> rgba(static_cast<size_t>(w) * h);
  for (int y = 0; y < h; ++y)  // GL's row 0 is the bottom
    for (int x = 0; x < w; ++x) rgba[static_cast<size_t>(h - 1 - y) * w + x] = glm::vec4(image.at(x, y), 1.0f);
  glTextureSubImage2D(impl_->radiance.id(), 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, rgba.data());
}

void Renderer::drawDisplay(const DisplaySettings& display, unsigned int framebuffer, int x, int y, int width,
                           int height) {
  Impl& m = *impl_;
  gl::PassScope pass("display");
  gl::Capability depthTest(GL_DEPTH_TEST, false), blend(GL_BLEND, false), scissor(GL_SCISSOR_TEST, false);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(x, y, width, height);
  const float bloom = std::clamp(display.bloom, 0.0f, 1.0f);
  const GLuint prog = bloom > 0.0f ? m.bloomPostProgram.id() : m.postProgram.id();
  glUseProgram(prog);
  glProgramUniform1f(prog, HAZE_LOC_POST_EXPOSURE, std::exp2(display.exposureEv) / DisplaySettings::kKeyNits);
  if (bloom > 0.0f) {
    glProgramUniform1f(prog, HAZE_LOC_POST_BLOOM, bloom);
    glGenerateTextureMipmap(m.radiance.id());
  }
  glBindTextureUnit(HAZE_UNIT_RADIANCE, m.radiance.id());
  const bool stretched = width != settings_.width || height != settings_.height;
  glBindSampler(HAZE_UNIT_RADIANCE, stretched ? m.stretchSampler.id() : 0);
  glBindTextureUnit(HAZE_UNIT_RADIANCE_MIPS, m.radiance.id());
  glBindSampler(HAZE_UNIT_RADIANCE_MIPS, m.mipSampler.id());
  glBindVertexArray(m.emptyVao.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindSampler(HAZE_UNIT_RADIANCE, 0);
  glBindSampler(HAZE_UNIT_RADIANCE_MIPS, 0);
}

std::vector<unsigned char> Renderer::readDisplay(const DisplaySettings& display) {
  Impl& m = *impl_;
  const int w = settings_.width, h = settings_.height;
  const auto t0 = std::chrono::steady_clock::now();
  drawDisplay(display, m.displayFbo.id(), 0, 0, w, h);
  std::vector<unsigned char> rgba(static_cast<size_t>(w) * h * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(m.display.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(rgba.size()), rgba.data());
  std::vector<unsigned char> rgb(static_cast<size_t>(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        rgb[(static_cast<size_t>(y) * w + x) * 3 + c] = rgba[(static_cast<size_t>(h - 1 - y) * w + x) * 4 + c];
  times_.postMs = msSince(t0);
  return rgb;
}

}  // namespace haze

namespace haze {

Metering Renderer::meter(const MeterSettings& settings) {
  Impl& m = *impl_;
  const auto t0 = std::chrono::steady_clock::now();
  // Box-filtered mip levels average the light over blocks: a lamp's lens or a thin beam edge
  // a few pixels wide then weighs by its area, as on a camera's metering sensor, and the
  // readback is a few thousand texels however large the image.
  constexpr int kMeterTexels = 64;
  const int longSide = std::max(settings_.width, settings_.height);
  int level = 0;
  while ((longSide >> (level + 1)) >= kMeterTexels) ++level;
  if (level > 0) glGenerateTextureMipmap(m.radiance.id());
  const int w = std::max(1, settings_.width >> level), h = std::max(1, settings_.height >> level);
  std::vector<glm::vec4> rgba(static_cast<size_t>(w) * h);
  glGetTextureImage(m.radiance.id(), level, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * sizeof(glm::vec4)),
                    rgba.data());
  std::vector<float> nits(rgba.size());
  for (size_t i = 0; i < rgba.size(); ++i) nits[i] = luminanceOf(glm::vec3(rgba[i]));
  const Metering result = meterLuminance(nits, settings);
  times_.meterMs = msSince(t0);
  return result;
}

}  // namespace haze
