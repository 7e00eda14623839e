#include "renderer/beam_resources.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "renderer/scene/depth_pyramid.h"

namespace haze {
namespace {

uint64_t mix(uint64_t h, uint64_t v) { return h ^ (v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2)); }

constexpr float kShadowNearM = 0.02f;

// The distance from the lens to the far corner of the venue's bounds.
float farthestCornerM(const glm::vec3& eye, const GpuVenue& venue) {
  float farM = 1.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c((i & 1) ? venue.boundsMax().x : venue.boundsMin().x,
                      (i & 2) ? venue.boundsMax().y : venue.boundsMin().y,
                      (i & 4) ? venue.boundsMax().z : venue.boundsMin().z);
    farM = std::max(farM, glm::length(c - eye));
  }
  return farM;
}

// Shadow frustum: the beam's cutoff cone, from a near plane close to the lens to the far
// corner of the venue's bounds.
glm::mat4 shadowViewProjection(const BeamState& b, float farM, float cutoffRad) {
  const glm::vec3 eye = b.pose.lensPosition;
  const float fov = std::min(2.0f * cutoffRad + glm::radians(2.0f), glm::radians(170.0f));
  const glm::mat4 view = glm::lookAt(eye, eye + b.pose.zb, b.pose.xb);
  return glm::perspective(fov, 1.0f, kShadowNearM, farM) * view;
}

// Whether an immutable texture got its storage (a driver out of memory leaves it without).
bool hasStorage(const gl::Texture& t) {
  GLint immutable = 0;
  glGetTextureParameteriv(t.id(), GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
  return immutable != 0;
}

// The light map's contents: the key the frame promises plus what bakeLightMap reads, so that
// beams share a layer only when their maps are equal.
uint64_t lightKey(const BeamState& b) {
  uint64_t h = mix(b.opticsKey, 1);
  h = mix(h, std::hash<const void*>{}(b.optics.distribution.get()));
  h = mix(h, std::hash<const void*>{}(b.optics.gobo.get()));
  h = mix(h, std::hash<const void*>{}(b.optics.gobo2.get()));
  h = mix(h, std::hash<const void*>{}(b.optics.animation.get()));
  for (float f : {b.optics.profileFieldAngleDeg, b.optics.fieldAngleDeg, b.optics.goboRotationDeg, b.optics.gobo2RotationDeg,
                  b.optics.animationAngleDeg, b.optics.iris, b.optics.focusBlur})
    h = mix(h, std::hash<float>{}(f));
  return h == 0 ? 1 : h;  // 0 is the "nothing baked" key
}

// The layer size that fits `beams` layers into the budget: at most `wanted`, a multiple of 16,
// at least 64 (below that a shadow map no longer resolves a person on a stage).
int shadowSizeFor(int beams, int wanted, int64_t budget) {
  if (beams <= 0) return wanted;
  const double fit = std::sqrt(static_cast<double>(budget) / static_cast<double>(beams));
  return std::clamp(static_cast<int>(fit) / 16 * 16, std::min(64, wanted), wanted);
}

// The beam's core (docs/rendering.md, "The core of a beam"): cos^2 of the half-angle outside
// which the light map holds under 1 % of its peak (a texel and a half of margin for the
// bilinear lookup), or 0 when its tangent is more than half the cutoff's: then the split would
// buy nothing and the whole chord is walked as one.
float coreCos2(const LightMap& map, float cutoffRad) {
  float peak = 0.0f;
  for (float c : map.cd) peak = std::max(peak, c);
  if (!(peak > 0.0f)) return 0.0f;
  float r2 = 0.0f;
  const float texel = 2.0f / static_cast<float>(map.size);
  for (int j = 0; j < map.size; ++j)
    for (int i = 0; i < map.size; ++i)
      if (map.cd[static_cast<size_t>(j) * map.size + i] >= 0.01f * peak) {
        const float u = (i + 0.5f) * texel - 1.0f, v = (j + 0.5f) * texel - 1.0f;
        r2 = std::max(r2, u * u + v * v);
      }
  // The map's (u, v) in [-1, 1] spans tan(theta) up to tan(cutoff).
  const float radius = std::sqrt(r2) + 1.5f * texel;
  if (radius > 0.5f) return 0.0f;
  const float tanCore = radius * std::tan(cutoffRad);
  return 1.0f / (1.0f + tanCore * tanCore);
}

}  // namespace

BeamResources::BeamResources(const BeamResourceSettings& settings) : settings_(settings) {
  const GLuint s = shadowDepthSampler_.id();
  glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(s, GL_TEXTURE_COMPARE_MODE, GL_NONE);
}

void BeamResources::ensureShadowCapacity(int beams) {
  if (maxLayers_ == 0) glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers_);
  // Layers in steps of 8, so that patching one more fixture rarely re-renders all the maps.
  const int capacity = std::min((std::max(beams, 1) + 7) / 8 * 8, maxLayers_);
  if (shadowMaps_ && capacity == shadowCapacity_) return;
  shadowCapacity_ = capacity;
  shadowSize_ = shadowSizeFor(capacity, settings_.shadowMapSize, settings_.shadowTexelBudget);
  for (;;) {
    shadowMaps_ = gl::Texture(GL_TEXTURE_2D_ARRAY, "shadow_maps");
    glTextureStorage3D(shadowMaps_.id(), 1, GL_DEPTH_COMPONENT32F, shadowSize_, shadowSize_, shadowCapacity_);
    if (hasStorage(shadowMaps_) || shadowSize_ <= 64) break;
    shadowSize_ = std::max(64, shadowSize_ / 2 / 16 * 16);  // the driver's own limit is lower than the budget
  }
  glTextureParameteri(shadowMaps_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(shadowMaps_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(shadowMaps_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(shadowMaps_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTextureParameteri(shadowMaps_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTextureParameteri(shadowMaps_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  if (!hasStorage(shadowMaps_)) shadowCapacity_ = 0;  // nothing can be shadowed: update() says so
  // The pyramid's levels side by side (shaders/beams.glsl, uShadowMin): level 0 at the origin,
  // the others in a column to its right.
  shadowMin_ = gl::Texture(GL_TEXTURE_2D_ARRAY, "shadow_min");
  const int minSize = (shadowSize_ + (1 << kDepthPyramidFirstShift) - 1) >> kDepthPyramidFirstShift;
  glTextureStorage3D(shadowMin_.id(), 1, GL_R32F, minSize + std::max(1, minSize / 2), minSize,
                     std::max(shadowCapacity_, 1));
  glTextureParameteri(shadowMin_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(shadowMin_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  // Least depth 0 until a map is rendered: nothing is surely lit.
  const float zero = 0.0f;
  glClearTexImage(shadowMin_.id(), 0, GL_RED, GL_FLOAT, &zero);
  shadowKeys_.assign(static_cast<size_t>(shadowCapacity_), 0);  // new layers hold nothing
  reachesM_.assign(static_cast<size_t>(shadowCapacity_), 1e30f);
}

void BeamResources::ensureLightCapacity(int layers) {
  if (maxLayers_ == 0) glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers_);
  layers = std::min(std::max(layers, 1), maxLayers_);
  if (lightMaps_ && layers <= lightCapacity_) return;
  lightCapacity_ = std::min(std::max({layers, 4, lightCapacity_ * 2}), maxLayers_);
  lightMaps_ = gl::Texture(GL_TEXTURE_2D_ARRAY, "light_maps");
  glTextureStorage3D(lightMaps_.id(), 1, GL_R32F, settings_.lightMapSize, settings_.lightMapSize, lightCapacity_);
  glTextureParameteri(lightMaps_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(lightMaps_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(lightMaps_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTextureParameteri(lightMaps_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float zero[4] = {0, 0, 0, 0};
  glTextureParameterfv(lightMaps_.id(), GL_TEXTURE_BORDER_COLOR, zero);
  if (!hasStorage(lightMaps_)) lightCapacity_ = 0;
  lightKeys_.assign(static_cast<size_t>(lightCapacity_), 0);
  extents_.assign(static_cast<size_t>(lightCapacity_), 1.0f);
  coreCos2_.assign(static_cast<size_t>(lightCapacity_), 0.0f);
}

float BeamResources::renderShadow(int layer, const glm::mat4& viewProj, float nearM, float farM, float cutoffRad,
                                  const GpuVenue& venue, const GpuBodies& bodies, const ShadowCasters& casters,
                                  const gl::Program& program) {
  glNamedFramebufferTextureLayer(shadowFbo_.id(), GL_DEPTH_ATTACHMENT, shadowMaps_.id(), 0, layer);
  glNamedFramebufferDrawBuffer(shadowFbo_.id(), GL_NONE);
  glBindFramebuffer(GL_FRAMEBUFFER, shadowFbo_.id());
  glViewport(0, 0, shadowSize_, shadowSize_);
  const float one = 1.0f;
  glClearNamedFramebufferfv(shadowFbo_.id(), GL_DEPTH, 0, &one);
  glUseProgram(program.id());
  glProgramUniformMatrix4fv(program.id(), HAZE_LOC_VIEW_PROJ, 1, GL_FALSE, glm::value_ptr(viewProj));
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);  // surfaces are two-sided (docs/physics.md)
  // Slope-scaled offset keeps lit surfaces from shadowing themselves at grazing angles.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 2.0f);
  venue.drawInside(viewProj);
  bodies.drawCasters(program.id(), casters.boxes, casters.meshes);
  glDisable(GL_POLYGON_OFFSET_FILL);

  // The farthest view depth the map sees; a texel at the far plane means light escapes.
  const int size = shadowSize_;
  depthScratch_.resize(static_cast<size_t>(size) * size);
  glGetTextureSubImage(shadowMaps_.id(), 0, 0, 0, layer, size, size, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                       static_cast<GLsizei>(depthScratch_.size() * sizeof(float)), depthScratch_.data());
  const DepthPyramid pyramid = buildDepthPyramid(depthScratch_, size);
  int originY = 0;
  for (size_t l = 0; l < pyramid.levels.size(); ++l) {
    const int n = pyramid.levelSize(static_cast<int>(l));
    glTextureSubImage3D(shadowMin_.id(), 0, l == 0 ? 0 : pyramid.size, l == 0 ? 0 : originY, layer, n, n, 1, GL_RED,
                        GL_FLOAT, pyramid.levels[l].data());
    if (l > 0) originY += n;
  }
  float maxDepth = 0.0f;
  for (float d : depthScratch_) maxDepth = std::max(maxDepth, d);
  if (maxDepth >= 1.0f) return farM;
  const float zNdc = 2.0f * maxDepth - 1.0f;
  const float viewZ = 2.0f * nearM * farM / (farM + nearM - zNdc * (farM - nearM));
  // A point at view depth z and angle a off the axis is z / cos(a) from the lens; a <= cutoff
  // inside the cone (plus a degree for the frustum's margin).
  return std::min(farM, viewZ / std::cos(std::min(cutoffRad + glm::radians(1.0f), glm::radians(85.0f))) * 1.01f);
}

BeamUpdateStats BeamResources::update(const FrameState& frame, const GpuVenue& venue, const GpuBodies& bodies,
                                      const gl::Program& shadowProgram) {
  BeamUpdateStats stats;
  softShadows_ = frame.softShadows;
  const int n = static_cast<int>(frame.beams.size());
  ensureShadowCapacity(n);
  stats.shadowMapSize = shadowSize_;

  // Light-map layers by content: kept where the content is still in use, else reused.
  std::vector<uint64_t> keys(static_cast<size_t>(n));
  std::unordered_map<uint64_t, int> layerOf;
  for (int i = 0; i < n; ++i) {
    keys[static_cast<size_t>(i)] = lightKey(frame.beams[static_cast<size_t>(i)]);
    layerOf.emplace(keys[static_cast<size_t>(i)], -1);
  }
  ensureLightCapacity(static_cast<int>(layerOf.size()));
  std::vector<int> freeLayers;
  for (int l = lightCapacity_ - 1; l >= 0; --l) {
    auto it = layerOf.find(lightKeys_[static_cast<size_t>(l)]);
    if (it != layerOf.end() && it->second < 0) it->second = l;
    else freeLayers.push_back(l);
  }
  const int size = settings_.lightMapSize;
  const std::vector<BodyBound> boxBounds = bodyBounds(frame.bodies), meshBounds = bodyBounds(frame.bodyMeshes);
  drawn_.assign(static_cast<size_t>(n), 0);
  gpuBeams_.resize(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const BeamState& b = frame.beams[static_cast<size_t>(i)];
    GpuBeam& g = gpuBeams_[static_cast<size_t>(i)];
    int& layer = layerOf[keys[static_cast<size_t>(i)]];
    if (layer < 0 && !freeLayers.empty()) {
      layer = freeLayers.back();
      freeLayers.pop_back();
      const LightMap map = b.optics.bakeLightMap(size);
      if (map.size == size && map.cd.size() == static_cast<size_t>(size) * size) {
        glTextureSubImage3D(lightMaps_.id(), 0, 0, 0, layer, size, size, 1, GL_RED, GL_FLOAT, map.cd.data());
        extents_[static_cast<size_t>(layer)] = map.extent;
        coreCos2_[static_cast<size_t>(layer)] = coreCos2(map, b.optics.cutoffHalfAngleRad());
      }
      lightKeys_[static_cast<size_t>(layer)] = keys[static_cast<size_t>(i)];
      ++stats.lightMapsBaked;
    }
    if (layer < 0 || i >= shadowCapacity_) {  // past the GL's layer limit: a dark, disc-less beam
      g = GpuBeam{};
      g.lensPos = glm::vec4(b.pose.lensPosition, 2.0f);  // cos(cutoff) > 1: no direction is inside
      stats.notDrawn.push_back(b.fixtureId);
      continue;
    }
    drawn_[static_cast<size_t>(i)] = 1;
    const float cutoff = b.optics.cutoffHalfAngleRad();
    const float farM = farthestCornerM(b.pose.lensPosition, venue) * 1.05f;
    const glm::mat4 viewProj = shadowViewProjection(b, farM, cutoff);
    // The casters bounded against the cone (the frustum only adds its corners, where I_eff is 0).
    const ShadowCasters casters = shadowCasters(b, cutoff, boxBounds, meshBounds);
    const uint64_t shadowKey = mix(mix(mix(b.poseKey, std::hash<float>{}(cutoff)), 2), casters.key);
    if (shadowKeys_[static_cast<size_t>(i)] != shadowKey) {
      reachesM_[static_cast<size_t>(i)] =
          renderShadow(i, viewProj, kShadowNearM, farM, cutoff, venue, bodies, casters, shadowProgram);
      shadowKeys_[static_cast<size_t>(i)] = shadowKey;
      ++stats.shadowMapsRendered;
    }
    const float tanHalfF = std::tan(glm::radians(b.optics.fieldAngleDeg) * 0.5f);
    g.lensPos = glm::vec4(b.pose.lensPosition, std::cos(cutoff));
    g.xb = glm::vec4(b.pose.xb, 1.0f / (tanHalfF * extents_[static_cast<size_t>(layer)]));
    g.yb = glm::vec4(b.pose.yb, static_cast<float>(layer));
    g.zb = glm::vec4(b.pose.zb, static_cast<float>(i));
    g.color = glm::vec4(b.optics.color * b.optics.dimmer, std::tan(cutoff));
    g.shadowViewProj = viewProj;
    // A radius of 0 draws no disc (a degenerate quad): tests use it to see the in-scattering alone.
    const float rl = std::max(b.optics.lensRadiusM, 0.0f);
    g.lens = glm::vec4(rl, rl > 0.0f ? 1.0f / (3.14159265f * rl * rl) : 0.0f, coreCos2_[static_cast<size_t>(layer)],
                       1.0f / std::max(reachesM_[static_cast<size_t>(i)], 1e-3f));
  }
  stats.lightMapLayers = static_cast<int>(layerOf.size());
  if (!stats.notDrawn.empty()) {
    stats.notDrawnReason = shadowCapacity_ == 0 || lightCapacity_ == 0
                               ? "the GL driver could not allocate the shadow or light maps"
                               : "the GL driver's limit of " + std::to_string(maxLayers_) +
                                     " texture array layers (one shadow map per beam)";
  }
  if (n > ssboCapacity_) {
    ssboCapacity_ = std::max(n, 2 * ssboCapacity_);
    ssbo_ = gl::Buffer("beams");
    glNamedBufferStorage(ssbo_.id(), static_cast<GLsizeiptr>(sizeof(GpuBeam) * ssboCapacity_), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
  }
  if (n > 0)
    glNamedBufferSubData(ssbo_.id(), 0, static_cast<GLsizeiptr>(sizeof(GpuBeam) * n), gpuBeams_.data());
  return stats;
}

void BeamResources::bind() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HAZE_SSBO_BEAMS, ssbo_.id());
  glBindTextureUnit(HAZE_UNIT_LIGHT_MAPS, lightMaps_.id());
  glBindTextureUnit(HAZE_UNIT_SHADOW_MAPS, shadowMaps_.id());
  glBindTextureUnit(HAZE_UNIT_SHADOW_DEPTH, shadowMaps_.id());
  glBindSampler(HAZE_UNIT_SHADOW_DEPTH, shadowDepthSampler_.id());
  glBindTextureUnit(HAZE_UNIT_SHADOW_MIN, shadowMin_.id());
}

void BeamResources::bindSoftShadows(unsigned int program) const {
  glProgramUniform1i(program, HAZE_LOC_SOFT_SHADOWS, softShadows_ ? 1 : 0);
  glProgramUniform1i(program, HAZE_LOC_SHADOW_MIN_ON, settings_.shadowMinPyramid && shadowCapacity_ > 0 ? 1 : 0);
}

}  // namespace haze
