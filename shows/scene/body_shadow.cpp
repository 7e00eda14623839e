// Which fixture bodies can shadow a beam (see body_shadow.h).
#include "shows/scene/body_shadow.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>

namespace haze {
namespace {

uint64_t mix(uint64_t h, uint64_t v) { return h ^ (v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2)); }

uint64_t hashFloats(uint64_t h, const float* f, size_t n) {
  for (size_t i = 0; i < n; ++i) {
    uint32_t bits;
    std::memcpy(&bits, &f[i], sizeof bits);
    h = mix(h, bits);
  }
  return h;
}

}  // namespace

std::vector<BodyBound> bodyBounds(const std::vector<BodyBox>& boxes) {
  std::vector<BodyBound> out;
  out.reserve(boxes.size());
  for (const BodyBox& b : boxes) {
    uint64_t key = hashFloats(1, &b.centerM.x, 3);
    key = hashFloats(key, &b.axes[0][0], 9);
    key = hashFloats(key, &b.halfSizeM.x, 3);
    out.push_back({b.centerM, glm::length(b.halfSizeM), b.fixtureId, key});
  }
  return out;
}

std::vector<BodyBound> bodyBounds(const std::vector<BodyMesh>& meshes) {
  std::vector<BodyBound> out;
  out.reserve(meshes.size());
  for (const BodyMesh& m : meshes) {
    if (!m.mesh || m.mesh->indices.empty()) {
      out.push_back({m.originM, -1.0f, m.fixtureId, 0});  // nothing to cast
      continue;
    }
    const glm::vec3 local = 0.5f * (m.mesh->boundsMin + m.mesh->boundsMax);
    uint64_t key = mix(2, reinterpret_cast<uintptr_t>(m.mesh.get()));
    key = hashFloats(key, &m.originM.x, 3);
    key = hashFloats(key, &m.axes[0][0], 9);
    out.push_back({m.originM + m.axes * local, 0.5f * glm::length(m.mesh->boundsMax - m.mesh->boundsMin), m.fixtureId,
                   key});
  }
  return out;
}

bool sphereMeetsCone(const glm::vec3& c, float r, const glm::vec3& apex, const glm::vec3& axis, float halfAngleRad) {
  const glm::vec3 d = c - apex;
  const float len = glm::length(d);
  if (len <= r) return true;
  const float angle = std::acos(std::clamp(glm::dot(d, axis) / len, -1.0f, 1.0f));
  return angle <= halfAngleRad + std::asin(std::min(r / len, 1.0f));
}

ShadowCasters shadowCasters(const BeamState& beam, float cutoffRad, const std::vector<BodyBound>& boxes,
                            const std::vector<BodyBound>& meshes) {
  ShadowCasters out;
  // A centimetre past the lens radius for float rounding in the sphere bounds.
  const float widenM = std::max(beam.optics.lensRadiusM, 0.0f) + 0.01f;
  uint64_t key = 3;
  auto take = [&](const std::vector<BodyBound>& bounds, std::vector<int>& list) {
    for (size_t k = 0; k < bounds.size(); ++k) {
      const BodyBound& b = bounds[k];
      if (b.fixtureId == beam.fixtureId || b.radiusM < 0.0f) continue;
      if (!sphereMeetsCone(b.centerM, b.radiusM + widenM, beam.pose.lensPosition, beam.pose.zb, cutoffRad)) continue;
      list.push_back(static_cast<int>(k));
      out.spheres.emplace_back(b.centerM, b.radiusM);
      key = mix(mix(key, k), b.poseKey);
    }
    key = mix(key, 0xffff);
  };
  take(boxes, out.boxes);
  take(meshes, out.meshes);
  out.key = out.empty() ? 0 : key;
  return out;
}

}  // namespace haze
