// Picking (see picking.h): the camera basis is the renderer's (shows/scene/camera_basis.h),
// so that a click lands where the pixel was drawn.
#include "shows/edit/picking.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include "fixtures/body.h"
#include "fixtures/pose.h"
#include "shows/scene/body_hit.h"
#include "shows/scene/camera_basis.h"

namespace haze {

ViewCamera::ViewCamera(const CameraState& camera, glm::vec2 viewportPx) : camera_(camera), viewportPx_(viewportPx) {
  viewportPx_ = glm::max(viewportPx_, glm::vec2(1.0f));
  const CameraBasis b = cameraBasis(camera, viewportPx_.x / viewportPx_.y);
  forward_ = b.forward;
  right_ = b.right;
  up_ = b.up;
  tanHalfFovY_ = b.tanY;
}

Ray ViewCamera::ray(glm::vec2 pixel) const {
  const float aspect = viewportPx_.x / viewportPx_.y;
  const float ndcX = 2.0f * pixel.x / viewportPx_.x - 1.0f;
  const float ndcY = 1.0f - 2.0f * pixel.y / viewportPx_.y;
  const glm::vec3 d = forward_ + right_ * (ndcX * tanHalfFovY_ * aspect) + up_ * (ndcY * tanHalfFovY_);
  return Ray{camera_.position, glm::normalize(d)};
}

std::optional<glm::vec2> ViewCamera::project(const glm::vec3& worldM) const {
  const glm::vec3 d = worldM - camera_.position;
  const float z = glm::dot(d, forward_);
  if (z <= camera_.nearM) return std::nullopt;
  const float aspect = viewportPx_.x / viewportPx_.y;
  const float ndcX = glm::dot(d, right_) / (z * tanHalfFovY_ * aspect);
  const float ndcY = glm::dot(d, up_) / (z * tanHalfFovY_);
  return glm::vec2((ndcX + 1.0f) * 0.5f * viewportPx_.x, (1.0f - ndcY) * 0.5f * viewportPx_.y);
}

std::optional<VenueHit> castVenue(const Bvh& bvh, const Ray& ray, float maxDistanceM) {
  const RayHit h = bvh.closestHit(ray.origin, ray.dir, 0.0f, maxDistanceM);
  if (!h.hit()) return std::nullopt;
  VenueHit v;
  v.surface = bvh.surfaceAt(h);
  v.distanceM = h.tM;
  v.normal = v.surface.geometricNormal;
  if (glm::dot(v.normal, ray.dir) > 0.0f) v.normal = -v.normal;  // the side the user sees
  return v;
}

std::optional<VenueHit> pickVenue(const Bvh& bvh, const ViewCamera& view, glm::vec2 pixel, float snapRadiusPx) {
  std::optional<VenueHit> best = castVenue(bvh, view.ray(pixel), view.camera().farM);
  if (snapRadiusPx <= 0.0f) return best;
  // Two rings of 8 rays: enough that a member 1 px wide within the radius is crossed.
  for (float r : {snapRadiusPx * 0.5f, snapRadiusPx}) {
    for (int k = 0; k < 8; ++k) {
      const float a = static_cast<float>(k) * glm::pi<float>() / 4.0f;
      auto h = castVenue(bvh, view.ray(pixel + r * glm::vec2(std::cos(a), std::sin(a))), view.camera().farM);
      // A surface a little nearer is the same wall seen at an angle; a thin thing in front of it is
      // much nearer (a truss 10 m ahead of a back wall).
      if (h && (!best || h->distanceM < best->distanceM * 0.9f)) best = h;
    }
  }
  return best;
}

glm::vec3 rotationForBeamDirection(const glm::vec3& dir) {
  // R = Ry(phi) Rx(theta) takes (0, -1, 0) to (-sin(theta) sin(phi), -cos(theta), -sin(theta) cos(phi)).
  const glm::vec3 d = glm::normalize(dir);
  const float thetaRad = std::acos(std::clamp(-d.y, -1.0f, 1.0f));
  const float horizontal = std::sqrt(d.x * d.x + d.z * d.z);
  const float phiRad = horizontal > 1e-6f ? std::atan2(-d.x, -d.z) : 0.0f;
  return {glm::degrees(thetaRad), glm::degrees(phiRad), 0.0f};
}

MountPose mountOnSurface(const VenueHit& hit) {
  MountPose m;
  m.positionM = hit.surface.positionM;
  const glm::vec3 n = hit.normal;
  if (n.y < -0.7f) {
    m.kind = MountPose::Kind::Hanging;
    return m;
  }
  if (n.y > 0.7f) {
    m.kind = MountPose::Kind::Standing;
    m.rotationDeg = {180.0f, 0.0f, 0.0f};
    return m;
  }
  if (const Primitive* p = hit.surface.primitive; p && !p->positions.empty()) {
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (const glm::vec3& v : p->positions) {
      lo = std::min(lo, v.y);
      hi = std::max(hi, v.y);
    }
    if (hi - lo <= kThinMemberM) {
      m.kind = MountPose::Kind::Hanging;
      m.positionM.y = lo;
      return m;
    }
  }
  m.kind = MountPose::Kind::Wall;
  m.rotationDeg = rotationForBeamDirection(n);
  return m;
}

std::optional<glm::vec3> intersectHorizontalPlane(const Ray& ray, float heightM) {
  if (std::abs(ray.dir.y) < 1e-6f) return std::nullopt;
  const float t = (heightM - ray.origin.y) / ray.dir.y;
  if (t <= 0.0f) return std::nullopt;
  return ray.origin + t * ray.dir;
}

glm::vec3 closestOnVerticalLine(const Ray& ray, const glm::vec3& pointM) {
  // Closest points of two lines: the ray and x = pointM + s (0, 1, 0).
  const glm::vec3 u = ray.dir, v(0.0f, 1.0f, 0.0f), w = ray.origin - pointM;
  const float a = glm::dot(u, u), b = glm::dot(u, v), c = 1.0f, d = glm::dot(u, w), e = glm::dot(v, w);
  const float den = a * c - b * b;
  if (den < 1e-9f) return pointM;  // looking straight along the line: keep the height
  const float s = (a * e - b * d) / den;
  return pointM + s * v;
}

namespace {

float distanceToSegmentPx(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
  const glm::vec2 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + t * ab));
}

}  // namespace

std::optional<int> pickFixtureBody(const Show& show, const ProfileSet& profiles, const StageState& state,
                                   const Ray& ray, float maxDistanceM, const Bvh* bvh) {
  // What the pointer sees: the venue hides a body behind it.
  float nearestM = maxDistanceM;
  if (bvh) {
    if (auto h = castVenue(*bvh, ray, maxDistanceM)) nearestM = h->distanceM;
  }
  std::optional<int> best;
  std::vector<BodyBox> boxes;
  std::vector<BodyMesh> meshes;
  for (const FixtureDef& f : show.fixtures) {
    const auto p = profiles.find(f.profile);
    if (p == profiles.end() || !p->second) continue;
    const auto st = state.find(f.id);
    const Attributes a = st != state.end() ? st->second : Attributes{};
    boxes.clear();
    meshes.clear();
    // Posed as the frame builder poses it for the renderer (shows/frame/frame_builder.cpp).
    poseBody(p->second->housing(), f.position, f.rotationDeg, a.panDeg, a.tiltDeg, boxes, &meshes);
    const BodyHit h = closestBody(boxes, meshes, bodyMeshAccels(meshes), ray.origin, ray.dir, nearestM);
    if (h.hit && h.tM < nearestM) {
      best = f.id;
      nearestM = h.tM;
    }
  }
  return best;
}

std::optional<int> pickFixture(const Show& show, const ProfileSet& profiles, const StageState& state,
                               const ViewCamera& view, glm::vec2 pixel, const Bvh* bvh, const PickOptions& options) {
  // 1. The body under the pointer (see picking.h for the order).
  if (auto body = pickFixtureBody(show, profiles, state, view.ray(pixel), view.camera().farM, bvh)) return body;

  // 2. The mounting point nearest the pointer.
  std::optional<int> best;
  float bestPx = options.bodyRadiusPx, bestDepth = std::numeric_limits<float>::infinity();
  for (const FixtureDef& f : show.fixtures) {
    const auto s = view.project(f.position);
    if (!s) continue;
    const float px = glm::length(*s - pixel);
    const float depth = glm::length(f.position - view.camera().position);
    if (px > options.bodyRadiusPx) continue;
    // Nearest to the pointer; markers within half a pixel of each other go to the nearer fixture.
    if (!best || px < bestPx - 0.5f || (px <= bestPx + 0.5f && depth < bestDepth)) {
      best = f.id;
      bestPx = px;
      bestDepth = depth;
    }
  }
  if (best) return best;

  // 3. A lit beam's axis.
  float bestBeamPx = options.beamRadiusPx;
  for (const FixtureDef& f : show.fixtures) {
    const auto st = state.find(f.id);
    if (st == state.end() || st->second.intensity <= 0.0f) continue;
    const auto p = profiles.find(f.profile);
    const glm::vec3 lens = p != profiles.end() && p->second ? p->second->lensOffset : glm::vec3(0.0f);
    const BeamPose pose = beamPose(f.position, f.rotationDeg, st->second.panDeg, st->second.tiltDeg, lens);
    float lengthM = options.beamLengthM;
    if (bvh) {
      if (auto h = castVenue(*bvh, Ray{pose.lensPosition, glm::normalize(pose.zb)}, options.beamLengthM * 4.0f))
        lengthM = h->distanceM;
    }
    // Clip the axis to what is in front of the camera before projecting it.
    glm::vec3 a = pose.lensPosition, b = pose.lensPosition + lengthM * glm::normalize(pose.zb);
    const glm::vec3 fwd = glm::normalize(view.camera().target - view.camera().position);
    const float za = glm::dot(a - view.camera().position, fwd), zb = glm::dot(b - view.camera().position, fwd);
    const float nearM = view.camera().nearM * 2.0f;
    if (za < nearM && zb < nearM) continue;
    if (za < nearM) a = a + (b - a) * ((nearM - za) / (zb - za));
    if (zb < nearM) b = a + (b - a) * ((nearM - za) / (zb - za));
    const auto sa = view.project(a), sb = view.project(b);
    if (!sa || !sb) continue;
    const float px = distanceToSegmentPx(pixel, *sa, *sb);
    if (px < bestBeamPx) {
      best = f.id;
      bestBeamPx = px;
    }
  }
  return best;
}

void applyClickToSelection(std::vector<int>& selection, std::optional<int> clicked, bool ctrl, bool shift) {
  if (!clicked) {
    if (!ctrl && !shift) selection.clear();
    return;
  }
  const auto it = std::find(selection.begin(), selection.end(), *clicked);
  if (ctrl) {
    if (it != selection.end()) selection.erase(it);
    else selection.push_back(*clicked);
  } else if (shift) {
    if (it == selection.end()) selection.push_back(*clicked);
  } else {
    selection = {*clicked};
  }
  std::sort(selection.begin(), selection.end());
}

}  // namespace haze
