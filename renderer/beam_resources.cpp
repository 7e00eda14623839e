#include "renderer/gl/scope.h"
#include "renderer/beam_resources.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <tuple>
#include <functional>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "shows/scene/depth_pyramid.h"

namespace haze {
namespace {

uint64_t mix(uint64_t h, uint64_t v) { return h ^ (v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2)); }

constexpr float kShadowNearM = 0.02f;
// Maps drawn before they are read back (without a budget): llvmpipe holds each drawn map's
// binned triangles until it is read, so the batch bounds that memory (all 76 of the Capture
// rig's at once took 57 MB more; four take 8 MB).
constexpr int kShadowReadBatch = 4;

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
  shadowViewProjs_.assign(static_cast<size_t>(shadowCapacity_), glm::mat4(1.0f));
  shadowFixtures_.assign(static_cast<size_t>(shadowCapacity_), 0);
  shadowStaleSince_.assign(static_cast<size_t>(shadowCapacity_), 0);
}

void BeamResources::ensureLightCapacity(int layers, bool keep) {
  if (maxLayers_ == 0) glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers_);
  layers = std::min(std::max(layers, 1), maxLayers_);
  if (lightMaps_ && layers <= lightCapacity_) return;
  const int oldCapacity = lightCapacity_;
  lightCapacity_ = std::min(std::max({layers, 4, lightCapacity_ * 2}), maxLayers_);
  gl::Texture old = std::move(lightMaps_);
  lightMaps_ = gl::Texture(GL_TEXTURE_2D_ARRAY, "light_maps");
  glTextureStorage3D(lightMaps_.id(), 1, GL_R32F, settings_.lightMapSize, settings_.lightMapSize, lightCapacity_);
  // Under a budget the old maps move into the new array: beams waiting for a new map keep
  // theirs, and nothing is baked again in one frame.
  if (keep && old && oldCapacity > 0 && hasStorage(lightMaps_)) {
    glCopyImageSubData(old.id(), GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0, lightMaps_.id(), GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0,
                       settings_.lightMapSize, settings_.lightMapSize, oldCapacity);
    const size_t c = static_cast<size_t>(lightCapacity_);
    lightKeys_.resize(c, 0);
    extents_.resize(c, 1.0f);
    coreCos2_.resize(c, 0.0f);
    lightScales_.resize(c, 1.0f);
  } else {
    keep = false;
  }
  glTextureParameteri(lightMaps_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(lightMaps_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(lightMaps_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTextureParameteri(lightMaps_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float zero[4] = {0, 0, 0, 0};
  glTextureParameterfv(lightMaps_.id(), GL_TEXTURE_BORDER_COLOR, zero);
  if (!hasStorage(lightMaps_)) lightCapacity_ = 0;
  if (keep) return;
  lightKeys_.assign(static_cast<size_t>(lightCapacity_), 0);
  extents_.assign(static_cast<size_t>(lightCapacity_), 1.0f);
  coreCos2_.assign(static_cast<size_t>(lightCapacity_), 0.0f);
  lightScales_.assign(static_cast<size_t>(lightCapacity_), 1.0f);
}

void BeamResources::drawShadow(int layer, const glm::mat4& viewProj, const GpuVenue& venue, const GpuBodies& bodies,
                               const ShadowCasters& casters, const gl::Program& program) {
  glNamedFramebufferTextureLayer(shadowFbo_.id(), GL_DEPTH_ATTACHMENT, shadowMaps_.id(), 0, layer);
  glNamedFramebufferDrawBuffer(shadowFbo_.id(), GL_NONE);
  glBindFramebuffer(GL_FRAMEBUFFER, shadowFbo_.id());
  glViewport(0, 0, shadowSize_, shadowSize_);
  const float one = 1.0f;
  glClearNamedFramebufferfv(shadowFbo_.id(), GL_DEPTH, 0, &one);
  glUseProgram(program.id());
  glProgramUniformMatrix4fv(program.id(), HAZE_LOC_VIEW_PROJ, 1, GL_FALSE, glm::value_ptr(viewProj));
  // Surfaces are two-sided (docs/physics.md); a slope-scaled offset keeps lit surfaces from
  // shadowing themselves at grazing angles.
  gl::Capability depthTest(GL_DEPTH_TEST, true), twoSided(GL_CULL_FACE, false), offset(GL_POLYGON_OFFSET_FILL, true);
  glDepthFunc(GL_LESS);
  glPolygonOffset(1.5f, 2.0f);
  venue.drawInside(viewProj);
  bodies.drawCasters(program.id(), casters.boxes, casters.meshes);
}

float BeamResources::readShadow(int layer, float nearM, float farM, float cutoffRad) {
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
  const auto start = std::chrono::steady_clock::now();
  ++updates_;
  UpdatePlan plan{.frame = &frame, .venue = &venue, .bodies = &bodies, .program = &shadowProgram,
                  .budgeted = settings_.mapWorkBudgetMs > 0.0};
  softShadows_ = frame.softShadows;
  const size_t n = frame.beams.size();
  ensureShadowCapacity(static_cast<int>(n));
  plan.stats.shadowMapSize = shadowSize_;
  drawnLightLayers_.resize(n, -1);
  drawnLightKeys_.resize(n, 0);
  drawnLightFixtures_.resize(n, 0);
  lightStaleSince_.resize(n, 0);

  assignLightLayers(plan);
  planShadows(plan);
  // The work without a budget, or where a beam has no usable old map, is done now; the rest
  // waits its turn in the schedule.
  std::vector<MapJob> deferred = doOrDefer(plan);
  const auto elapsedMs = [&] {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  };
  schedule_.run(std::move(deferred), settings_.mapWorkBudgetMs, elapsedMs, [&](const MapJob& job) {
    const size_t i = static_cast<size_t>(job.beam);
    if (job.kind == MapKind::Shadow) {
      drawNow(plan, job.beam);
      return true;
    }
    if (plan.layerOf[plan.keys[i]] >= 0) return false;  // another beam with this content was baked already
    bake(plan, i);
    return true;
  });
  readUnread(plan);
  writeGpuBeams(plan);
  uploadBeams();
  return plan.stats;
}

// Light-map layers by content: kept where the content is still in use, else reused. Under a
// budget a beam whose light map changed may keep its old one (its fallback) for a while: the
// layers that hold those stay in use too.
void BeamResources::assignLightLayers(UpdatePlan& plan) {
  const FrameState& frame = *plan.frame;
  const size_t n = frame.beams.size();
  plan.keys.resize(n);
  for (size_t i = 0; i < n; ++i) {
    plan.keys[i] = lightKey(frame.beams[i]);
    plan.layerOf.emplace(plan.keys[i], -1);
  }
  std::unordered_map<uint64_t, int> held;  // fallback content -> its layer
  if (plan.budgeted) {
    const std::unordered_set<uint64_t> baked(lightKeys_.begin(), lightKeys_.end());
    for (size_t i = 0; i < n; ++i)
      if (const int l = fallbackLayer(frame, i);
          l >= 0 && !baked.contains(plan.keys[i]) && !plan.layerOf.contains(drawnLightKeys_[i]))
        held.emplace(drawnLightKeys_[i], l);
  }
  ensureLightCapacity(static_cast<int>(plan.layerOf.size() + held.size()), plan.budgeted);
  for (int l = lightCapacity_ - 1; l >= 0; --l) {
    const uint64_t k = lightKeys_[static_cast<size_t>(l)];
    auto it = plan.layerOf.find(k);
    if (it != plan.layerOf.end() && it->second < 0) it->second = l;
    else if (!held.contains(k)) plan.freeLayers.push_back(l);
  }
  plan.fallback.assign(n, -1);
  for (size_t i = 0; i < n; ++i)
    if (plan.budgeted && plan.layerOf[plan.keys[i]] < 0) {
      const int l = fallbackLayer(frame, i);
      const uint64_t k = l >= 0 ? lightKeys_[static_cast<size_t>(l)] : 0;
      if (l >= 0 && (held.contains(k) || plan.layerOf.contains(k))) plan.fallback[i] = l;
    }
}

// The layer beam i was last drawn with, while it still holds what it held then for the same
// fixture; -1 when there is none.
int BeamResources::fallbackLayer(const FrameState& frame, size_t i) const {
  const int l = drawnLightLayers_[i];
  if (l < 0 || l >= lightCapacity_ || drawnLightFixtures_[i] != frame.beams[i].fixtureId ||
      lightKeys_[static_cast<size_t>(l)] != drawnLightKeys_[i] || drawnLightKeys_[i] == 0)
    return -1;
  return l;
}

// What each beam's shadow map would be drawn with this frame.
void BeamResources::planShadows(UpdatePlan& plan) {
  const FrameState& frame = *plan.frame;
  const std::vector<BodyBound> boxBounds = bodyBounds(frame.bodies), meshBounds = bodyBounds(frame.bodyMeshes);
  plan.shadowJobs.resize(static_cast<size_t>(std::min(static_cast<int>(frame.beams.size()), shadowCapacity_)));
  for (size_t i = 0; i < plan.shadowJobs.size(); ++i) {
    const BeamState& b = frame.beams[i];
    ShadowJob& j = plan.shadowJobs[i];
    j.cutoff = b.optics.cutoffHalfAngleRad();
    j.farM = farthestCornerM(b.pose.lensPosition, *plan.venue) * 1.05f;
    j.viewProj = shadowViewProjection(b, j.farM, j.cutoff);
    // The casters bounded against the cone (the frustum only adds its corners, where I_eff is 0).
    j.casters = shadowCasters(b, j.cutoff, boxBounds, meshBounds);
    j.key = mix(mix(mix(b.poseKey, std::hash<float>{}(j.cutoff)), 2), j.casters.key);
  }
}

// Bakes and draws what must be done now; returns the jobs that may wait (under a budget, where
// the beam has a usable old map to show meanwhile), each stale since the first update that
// found it so.
std::vector<MapJob> BeamResources::doOrDefer(UpdatePlan& plan) {
  const FrameState& frame = *plan.frame;
  std::vector<MapJob> deferred;
  for (size_t l = 0; l < frame.beams.size(); ++l) {
    const int i = static_cast<int>(l);
    if (plan.layerOf[plan.keys[l]] < 0) {
      if (plan.fallback[l] < 0) {
        bake(plan, l);
      } else {
        if (lightStaleSince_[l] == 0) lightStaleSince_[l] = updates_;
        deferred.push_back({lightStaleSince_[l], i, MapKind::Light});
      }
    }
    // A beam with neither light map is not drawn (past the GL's layer limit): no shadow map either.
    if (plan.layerOf[plan.keys[l]] < 0 && plan.fallback[l] < 0) continue;
    if (l >= plan.shadowJobs.size() || shadowKeys_[l] == plan.shadowJobs[l].key) continue;
    const bool usable = shadowKeys_[l] != 0 && shadowFixtures_[l] == frame.beams[l].fixtureId;
    if (!plan.budgeted || !usable) {
      drawNow(plan, i);
    } else {
      if (shadowStaleSince_[l] == 0) shadowStaleSince_[l] = updates_;
      deferred.push_back({shadowStaleSince_[l], i, MapKind::Shadow});
    }
  }
  return deferred;
}

void BeamResources::bake(UpdatePlan& plan, size_t i) {
  int& layer = plan.layerOf[plan.keys[i]];
  if (layer >= 0 || plan.freeLayers.empty()) return;
  const BeamState& b = plan.frame->beams[i];
  layer = plan.freeLayers.back();
  plan.freeLayers.pop_back();
  const size_t ll = static_cast<size_t>(layer);
  const int size = settings_.lightMapSize;
  const LightMap map = b.optics.bakeLightMap(size);
  if (map.size == size && map.cd.size() == static_cast<size_t>(size) * size) {
    glTextureSubImage3D(lightMaps_.id(), 0, 0, 0, layer, size, size, 1, GL_RED, GL_FLOAT, map.cd.data());
    extents_[ll] = map.extent;
    coreCos2_[ll] = coreCos2(map, b.optics.cutoffHalfAngleRad());
  }
  lightScales_[ll] = 1.0f / (std::tan(glm::radians(b.optics.fieldAngleDeg) * 0.5f) * extents_[ll]);
  lightKeys_[ll] = plan.keys[i];
  ++plan.stats.lightMapsBaked;
}

// Without a budget the maps' readbacks (each waits for its map) come after a batch is drawn: the
// GL rasterises one map while the next is being set up, instead of idling through each readback.
// With a budget each map is read at once, so that its time counts against the budget.
void BeamResources::drawNow(UpdatePlan& plan, int i) {
  const size_t l = static_cast<size_t>(i);
  const ShadowJob& j = plan.shadowJobs[l];
  drawShadow(i, j.viewProj, *plan.venue, *plan.bodies, j.casters, *plan.program);
  plan.unread.push_back(i);
  if (plan.budgeted || plan.unread.size() >= static_cast<size_t>(kShadowReadBatch)) readUnread(plan);
  shadowKeys_[l] = j.key;
  shadowViewProjs_[l] = j.viewProj;
  shadowFixtures_[l] = plan.frame->beams[l].fixtureId;
  ++plan.stats.shadowMapsRendered;
}

void BeamResources::readUnread(UpdatePlan& plan) {
  for (int i : plan.unread) {
    const ShadowJob& j = plan.shadowJobs[static_cast<size_t>(i)];
    reachesM_[static_cast<size_t>(i)] = readShadow(i, kShadowNearM, j.farM, j.cutoff);
  }
  plan.unread.clear();
}

// The storage buffer's entries: each beam with the maps it has this frame (an old light map
// keeps the scale it was baked for, an old shadow map the matrix it was drawn with, so lookups
// read the texels they index), or dark past the GL's layer limit.
void BeamResources::writeGpuBeams(UpdatePlan& plan) {
  const FrameState& frame = *plan.frame;
  const size_t n = frame.beams.size();
  drawn_.assign(n, 0);
  gpuBeams_.resize(n);
  for (size_t l = 0; l < n; ++l) {
    const BeamState& b = frame.beams[l];
    GpuBeam& g = gpuBeams_[l];
    const int current = plan.layerOf[plan.keys[l]];
    const int layer = current >= 0 ? current : plan.fallback[l];
    if (layer < 0 || l >= static_cast<size_t>(shadowCapacity_)) {
      g = GpuBeam{};
      g.lensPos = glm::vec4(b.pose.lensPosition, 2.0f);  // cos(cutoff) > 1: no direction is inside
      plan.stats.notDrawn.push_back(b.fixtureId);
      drawnLightLayers_[l] = -1;
      continue;
    }
    drawn_[l] = 1;
    const size_t ll = static_cast<size_t>(layer);
    drawnLightLayers_[l] = layer;
    drawnLightKeys_[l] = lightKeys_[ll];
    drawnLightFixtures_[l] = b.fixtureId;
    const ShadowJob& j = plan.shadowJobs[l];
    const bool shadowCurrent = shadowKeys_[l] == j.key;
    if (shadowCurrent) shadowStaleSince_[l] = 0;
    if (current >= 0) lightStaleSince_[l] = 0;
    plan.stats.mapsPending += !shadowCurrent || current < 0;
    const float tanHalfF = std::tan(glm::radians(b.optics.fieldAngleDeg) * 0.5f);
    g.lensPos = glm::vec4(b.pose.lensPosition, std::cos(j.cutoff));
    g.xb = glm::vec4(b.pose.xb, current >= 0 ? 1.0f / (tanHalfF * extents_[ll]) : lightScales_[ll]);
    g.yb = glm::vec4(b.pose.yb, static_cast<float>(layer));
    g.zb = glm::vec4(b.pose.zb, static_cast<float>(l));
    g.color = glm::vec4(b.optics.color * b.optics.dimmer, std::tan(j.cutoff));
    g.shadowViewProj = shadowCurrent ? j.viewProj : shadowViewProjs_[l];
    // A radius of 0 draws no disc (a degenerate quad): tests use it to see the in-scattering alone.
    const float rl = std::max(b.optics.lensRadiusM, 0.0f);
    g.lens = glm::vec4(rl, rl > 0.0f ? 1.0f / (3.14159265f * rl * rl) : 0.0f, coreCos2_[ll],
                       1.0f / std::max(reachesM_[l], 1e-3f));
  }
  plan.stats.lightMapLayers = static_cast<int>(plan.layerOf.size());
  if (!plan.stats.notDrawn.empty()) {
    plan.stats.notDrawnReason = shadowCapacity_ == 0 || lightCapacity_ == 0
                                    ? "the GL driver could not allocate the shadow or light maps"
                                    : "the GL driver's limit of " + std::to_string(maxLayers_) +
                                          " texture array layers (one shadow map per beam)";
  }
}

void BeamResources::uploadBeams() {
  const int n = static_cast<int>(gpuBeams_.size());
  if (n > ssboCapacity_) {
    ssboCapacity_ = std::max(n, 2 * ssboCapacity_);
    ssbo_ = gl::Buffer("beams");
    glNamedBufferStorage(ssbo_.id(), static_cast<GLsizeiptr>(sizeof(GpuBeam) * ssboCapacity_), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
  }
  if (n > 0)
    glNamedBufferSubData(ssbo_.id(), 0, static_cast<GLsizeiptr>(sizeof(GpuBeam) * n), gpuBeams_.data());
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
