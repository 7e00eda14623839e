// Rays against posed fixture bodies (see body_hit.h).
#include "shows/scene/body_hit.h"

#include <map>
#include <mutex>
#include <utility>

#include <glm/matrix.hpp>

namespace haze {

std::shared_ptr<const MeshAccel> meshAccel(const std::shared_ptr<const TriangleMesh>& mesh) {
  static std::mutex lock;
  static std::map<const TriangleMesh*, std::pair<std::weak_ptr<const TriangleMesh>, std::shared_ptr<const MeshAccel>>> cache;
  const std::lock_guard<std::mutex> guard(lock);
  for (auto it = cache.begin(); it != cache.end();)
    it = it->second.first.expired() ? cache.erase(it) : std::next(it);
  auto& slot = cache[mesh.get()];
  if (!slot.second) {
    auto accel = std::make_shared<MeshAccel>();
    Primitive p;
    p.name = "body mesh";
    p.positions = mesh->positions;
    p.normals = mesh->normals;
    p.indices = mesh->indices;
    accel->venue.primitives.push_back(std::move(p));
    accel->venue.materials.emplace_back();
    accel->bvh = std::make_unique<Bvh>(accel->venue);
    slot = {mesh, std::move(accel)};
  }
  return slot.second;
}

std::vector<std::shared_ptr<const MeshAccel>> bodyMeshAccels(const std::vector<BodyMesh>& meshes) {
  std::vector<std::shared_ptr<const MeshAccel>> out;
  out.reserve(meshes.size());
  for (const BodyMesh& m : meshes) out.push_back(m.mesh ? meshAccel(m.mesh) : nullptr);
  return out;
}

BodyHit closestBody(const std::vector<BodyBox>& boxes, const std::vector<BodyMesh>& meshes,
                    const std::vector<std::shared_ptr<const MeshAccel>>& accels, const glm::vec3& origin,
                    const glm::vec3& dir, float tMaxM) {
  BodyHit best;
  for (size_t k = 0; k < boxes.size(); ++k) {
    const BodyBox& b = boxes[k];
    const BoxHit h = intersectBox(b, origin, dir, best.hit ? best.tM : tMaxM);
    if (h.hit) best = {true, h.tM, h.normal, h.normal, b.albedo, static_cast<int>(k), -1};
  }
  for (size_t k = 0; k < meshes.size() && k < accels.size(); ++k) {
    if (!accels[k]) continue;
    const BodyMesh& m = meshes[k];
    const glm::mat3 toLocal = glm::transpose(m.axes);
    const RayHit h =
        accels[k]->bvh->closestHit(toLocal * (origin - m.originM), toLocal * dir, 0.0f, best.hit ? best.tM : tMaxM);
    if (!h.hit()) continue;
    const SurfacePoint sp = accels[k]->bvh->surfaceAt(h);
    best = {true, h.tM, m.axes * sp.geometricNormal, m.axes * sp.shadingNormal, m.albedo, -1, static_cast<int>(k)};
  }
  return best;
}

bool anyBodyHit(const std::vector<BodyBox>& boxes, const std::vector<BodyMesh>& meshes,
                const std::vector<std::shared_ptr<const MeshAccel>>& accels, const std::vector<int>& boxList,
                const std::vector<int>& meshList, const glm::vec3& origin, const glm::vec3& dir, float tMinM,
                float tMaxM) {
  if (!(tMaxM > tMinM)) return false;
  const glm::vec3 start = origin + dir * tMinM;
  for (int k : boxList)
    if (intersectBox(boxes[static_cast<size_t>(k)], start, dir, tMaxM - tMinM).hit) return true;
  for (int k : meshList) {
    const size_t i = static_cast<size_t>(k);
    if (i >= accels.size() || !accels[i]) continue;
    const BodyMesh& m = meshes[i];
    const glm::mat3 toLocal = glm::transpose(m.axes);
    if (accels[i]->bvh->anyHit(toLocal * (origin - m.originM), toLocal * dir, tMinM, tMaxM)) return true;
  }
  return false;
}

}  // namespace haze
