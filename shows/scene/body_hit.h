// Rays against posed fixture bodies (docs/rendering.md, "Fixture bodies"): the boxes exactly
// (intersectBox), the meshes through a BVH of each mesh in its part's frame, the ray taken into
// that frame. The CPU reference shades what this finds and the editor picks a fixture by it, so
// a click selects the housing the user sees under the pointer.
#pragma once

#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "fixtures/body.h"
#include "shows/scene/bvh.h"
#include "shows/scene/venue.h"

namespace haze {

// A body mesh's own BVH, in its part's frame.
struct MeshAccel {
  Venue venue;
  std::unique_ptr<Bvh> bvh;
};

// Built once per distinct mesh and kept while the mesh lives (a cache keyed by the mesh, safe
// across threads), so every frame of a move and every click reuses it.
std::shared_ptr<const MeshAccel> meshAccel(const std::shared_ptr<const TriangleMesh>& mesh);
// The accelerations of posed meshes, by index into `meshes` (null where a mesh is null).
std::vector<std::shared_ptr<const MeshAccel>> bodyMeshAccels(const std::vector<BodyMesh>& meshes);

// The nearest body surface on the ray (origin, unit dir) before tMaxM: boxes, then meshes
// (accels[k] belongs to meshes[k]). `box` / `mesh` say which one was hit (-1: none / the other).
struct BodyHit {
  bool hit = false;
  float tM = 0.0f;
  glm::vec3 geometricNormal{0.0f};
  glm::vec3 shadingNormal{0.0f};
  glm::vec3 albedo{0.0f};
  int box = -1;
  int mesh = -1;
};
BodyHit closestBody(const std::vector<BodyBox>& boxes, const std::vector<BodyMesh>& meshes,
                    const std::vector<std::shared_ptr<const MeshAccel>>& accels, const glm::vec3& origin,
                    const glm::vec3& dir, float tMaxM);

// Whether the ray (origin, unit dir) meets any of the listed bodies (indices into boxes and
// meshes) between tMinM and tMaxM: V(x) against other fixtures' bodies (body_shadow.h).
bool anyBodyHit(const std::vector<BodyBox>& boxes, const std::vector<BodyMesh>& meshes,
                const std::vector<std::shared_ptr<const MeshAccel>>& accels, const std::vector<int>& boxList,
                const std::vector<int>& meshList, const glm::vec3& origin, const glm::vec3& dir, float tMinM,
                float tMaxM);

}  // namespace haze
