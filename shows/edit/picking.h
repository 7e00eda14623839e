// Picking for the GUI without a window: screen point -> ray, ray -> venue surface (the venue's
// triangles through the reference BVH), where a fixture placed on that surface hangs or stands,
// and which fixture (its body or its beam) is under the pointer. The GUI and its unit tests
// share this, so what a click does is tested with no GL and no ImGui.
#pragma once

#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shows/scene/bvh.h"
#include "shows/scene/frame_state.h"
#include "shows/playback.h"
#include "shows/show.h"

namespace haze {

struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 dir{0.0f, 0.0f, -1.0f};  // unit
};

// The camera as the renderer draws it (glm::lookAt, glm::perspective, aspect = width / height)
// on a viewport of viewportPx pixels, pixel (0, 0) at the top left.
class ViewCamera {
 public:
  ViewCamera(const CameraState& camera, glm::vec2 viewportPx);
  // The ray through a pixel position (pixel centres at +0.5).
  Ray ray(glm::vec2 pixel) const;
  // Where a world point lands on screen; empty when it is behind the camera.
  std::optional<glm::vec2> project(const glm::vec3& worldM) const;
  const CameraState& camera() const { return camera_; }

 private:
  CameraState camera_;
  glm::vec2 viewportPx_;
  glm::vec3 forward_, right_, up_;
  float tanHalfFovY_;
};

struct VenueHit {
  SurfacePoint surface;
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // geometric normal turned to face the ray's origin
  float distanceM = 0.0f;
};

// The nearest venue surface along the ray through `pixel`. With snapRadiusPx > 0, rays through
// a ring of pixels around it are tried too and the nearest surface among them wins, so thin
// things in front (a truss chord 5 cm wide, a pipe) can be hit without pixel-exact aim.
std::optional<VenueHit> pickVenue(const Bvh& bvh, const ViewCamera& view, glm::vec2 pixel,
                                  float snapRadiusPx = 0.0f);
std::optional<VenueHit> castVenue(const Bvh& bvh, const Ray& ray, float maxDistanceM = 1000.0f);

// Where and how a fixture goes when placed on a surface (the fixture's position is its mounting
// point, as for the demo's truss fixtures at the truss's underside):
// - under a surface that faces down (a truss's underside, a ceiling) it hangs: rotation 0, the
//   beam at rest points down;
// - on a surface that faces up (a floor, a riser) it stands: rotation [180, 0, 0], beam up;
// - on the side of a thin horizontal member (a truss chord, a pipe: at most kThinMemberM tall)
//   it hangs from that member's underside below the hit;
// - on a wall it is mounted with the beam at rest pointing out of the wall along the normal.
struct MountPose {
  glm::vec3 positionM{0.0f};
  glm::vec3 rotationDeg{0.0f};
  enum class Kind { Hanging, Standing, Wall } kind = Kind::Hanging;
};
inline constexpr float kThinMemberM = 0.3f;
MountPose mountOnSurface(const VenueHit& hit);
// The mounting rotation (degrees, R = Rz Ry Rx) whose resting beam (-Y) points along `dir`.
glm::vec3 rotationForBeamDirection(const glm::vec3& dir);

// Where a ray meets the horizontal plane y = heightM (moving a fixture by drag); empty when the
// ray runs parallel to it or the plane is behind the origin.
std::optional<glm::vec3> intersectHorizontalPlane(const Ray& ray, float heightM);
// Where a ray comes closest to the vertical line through `pointM` (dragging a fixture up and
// down): the point on that line.
glm::vec3 closestOnVerticalLine(const Ray& ray, const glm::vec3& pointM);

// The fixture under the pointer, in this order:
// 1. the body the ray through the pixel meets first (pickFixtureBody: the housing's boxes and
//    meshes as the renderer draws them, posed with the fixture's position, rotation and the
//    pan/tilt in `state`), when it is nearer than the venue surface on that ray (given a BVH):
//    what is seen under the pointer is what is picked, never a body behind a wall;
// 2. else its mounting point (the marker, within bodyRadiusPx on screen), nearest to the
//    pointer (then to the camera);
// 3. else a lit beam whose axis passes within beamRadiusPx of the pointer (the axis from the
//    lens to where it meets the venue, or beamLengthM when nothing is hit or no BVH is given).
// Empty when nothing is near.
struct PickOptions {
  float bodyRadiusPx = 10.0f;
  float beamRadiusPx = 4.0f;
  float beamLengthM = 15.0f;
};
// The fixture whose posed body the ray meets first before maxDistanceM and before the venue
// (when a BVH is given); empty when it meets none.
std::optional<int> pickFixtureBody(const Show& show, const ProfileSet& profiles, const StageState& state,
                                   const Ray& ray, float maxDistanceM, const Bvh* bvh = nullptr);
std::optional<int> pickFixture(const Show& show, const ProfileSet& profiles, const StageState& state,
                               const ViewCamera& view, glm::vec2 pixel, const Bvh* bvh = nullptr,
                               const PickOptions& options = {});

// How a click changes the selection (Ctrl toggles, Shift adds, a plain click replaces; a click
// on nothing with neither clears it). Kept sorted by id, so multi-edits go in a stable order.
void applyClickToSelection(std::vector<int>& selection, std::optional<int> clicked, bool ctrl, bool shift);

}  // namespace haze
