// Which fixture bodies can shadow a beam (docs/rendering.md, "Fixture bodies"; docs/physics.md,
// section 7): every other fixture's body whose bounding sphere meets the beam's cone widened by
// the lens radius. The GPU draws exactly these into the beam's shadow map and keys the map on
// their poses, so a head that pans redraws only the maps of beams it can lie in; the reference
// tests exactly these in V(x). A fixture's own body (all its cells' beams) never shadows it.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "fixtures/body.h"
#include "shows/scene/frame_state.h"

namespace haze {

// A posed body's bounding sphere, its fixture, and a key that changes when it moves.
struct BodyBound {
  glm::vec3 centerM{0.0f};
  float radiusM = 0.0f;
  int fixtureId = 0;
  uint64_t poseKey = 0;
};
std::vector<BodyBound> bodyBounds(const std::vector<BodyBox>& boxes);
std::vector<BodyBound> bodyBounds(const std::vector<BodyMesh>& meshes);

// Whether the sphere (centre c, radius r) meets the cone of unit axis and half-angle
// halfAngleRad (< 90 degrees) from apex (conservative: exact for the cone, which is convex).
bool sphereMeetsCone(const glm::vec3& c, float r, const glm::vec3& apex, const glm::vec3& axis, float halfAngleRad);

struct ShadowCasters {
  std::vector<int> boxes;   // indices into FrameState::bodies
  std::vector<int> meshes;  // indices into FrameState::bodyMeshes
  std::vector<glm::vec4> spheres;  // every caster's bound (centre, radius), boxes then meshes
  uint64_t key = 0;         // the casters and their poses; 0 for none
  bool empty() const { return boxes.empty() && meshes.empty(); }
};
// The bodies that can shadow `beam` (cone of half-angle cutoffRad): not its fixture's, and
// meeting the cone widened by the lens radius (every segment from the lens disc to a point of
// the cone lies within r_lens of the segment from the lens centre).
ShadowCasters shadowCasters(const BeamState& beam, float cutoffRad, const std::vector<BodyBound>& boxes,
                            const std::vector<BodyBound>& meshes);

}  // namespace haze
