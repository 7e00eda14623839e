// Places the imported rig's overview camera: candidate viewpoints around the rig's middle,
// each checked with rays against the venue (MvrRayScene), the one that sees most of the rig wins.
#include "shows/mvr_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace haze {

namespace {
constexpr std::size_t kRun = 32;  // triangles per box

// Slab test: does origin + t * dir, 0 <= t <= maxM, pass through the box?
bool crossesBox(const glm::vec3& origin, const glm::vec3& invDir, float maxM, const glm::vec3& lo, const glm::vec3& hi) {
  float t0 = 0.0f, t1 = maxM;
  for (int k = 0; k < 3; ++k) {
    float a = (lo[k] - origin[k]) * invDir[k], b = (hi[k] - origin[k]) * invDir[k];
    if (std::isnan(a) || std::isnan(b)) {  // dir[k] = 0 with the origin on a face: inside that slab
      if (origin[k] < lo[k] || origin[k] > hi[k]) return false;
      continue;
    }
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  return true;
}
}  // namespace

MvrRayScene::MvrRayScene(std::vector<glm::vec3> trianglesM) : triangles_(std::move(trianglesM)) {
  triangles_.resize(triangles_.size() / 3 * 3);
  for (std::size_t i = 0; i < triangles_.size(); i += 3 * kRun) {
    Box b{triangles_[i], triangles_[i]};
    for (std::size_t j = i; j < std::min(triangles_.size(), i + 3 * kRun); ++j) {
      b.lo = glm::min(b.lo, triangles_[j]);
      b.hi = glm::max(b.hi, triangles_[j]);
    }
    boxes_.push_back(b);
  }
}

float MvrRayScene::firstHitM(const glm::vec3& origin, const glm::vec3& dir, float maxM) const {
  const glm::vec3 invDir = 1.0f / dir;  // +-inf on an axis the ray runs across
  float best = maxM;
  bool hit = false;
  for (std::size_t b = 0; b < boxes_.size(); ++b) {
    if (!crossesBox(origin, invDir, best, boxes_[b].lo, boxes_[b].hi)) continue;
    const std::size_t end = std::min(triangles_.size(), (b + 1) * 3 * kRun);
    for (std::size_t i = b * 3 * kRun; i < end; i += 3) {
      // Moller-Trumbore.
      const glm::vec3 e1 = triangles_[i + 1] - triangles_[i], e2 = triangles_[i + 2] - triangles_[i];
      const glm::vec3 p = glm::cross(dir, e2);
      const float det = glm::dot(e1, p);
      if (std::abs(det) < 1e-12f) continue;
      const float inv = 1.0f / det;
      const glm::vec3 s = origin - triangles_[i];
      const float u = glm::dot(s, p) * inv;
      if (u < 0.0f || u > 1.0f) continue;
      const glm::vec3 q = glm::cross(s, e1);
      const float v = glm::dot(dir, q) * inv;
      if (v < 0.0f || u + v > 1.0f) continue;
      const float t = glm::dot(e2, q) * inv;
      if (t > 1e-6f && t < best) {
        best = t;
        hit = true;
      }
    }
  }
  return hit ? best : -1.0f;
}

CameraDef mvrOverviewCamera(const std::vector<glm::vec3>& rigPointsM, const MvrRayScene& venue) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& p : rigPointsM) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float extent = std::max(4.0f, glm::length(hi - lo));
  // The open-stage view: back 1.2 extents towards the audience, 0.4 up (18.4 degrees).
  const float wantedM = extent * std::sqrt(1.2f * 1.2f + 0.4f * 0.4f);
  constexpr float kMarginM = 0.3f;      // stand this far in front of a wall or ceiling
  constexpr float kMinRoomM = 1.0f;     // less room than this is no viewpoint
  constexpr float kNearPointM = 0.5f;   // a rig point counts as seen when the line reaches this near
  constexpr std::size_t kMaxPoints = 48;
  // The rig points that are checked: at most 48, spread over the list.
  std::vector<glm::vec3> sample;
  const std::size_t step = (rigPointsM.size() + kMaxPoints - 1) / kMaxPoints;
  for (std::size_t i = 0; i < rigPointsM.size(); i += step) sample.push_back(rigPointsM[i]);
  const float elevationsDeg[] = {glm::degrees(std::atan(0.4f / 1.2f)), 12.0f, 6.0f, 0.0f};
  const float azimuthsDeg[] = {0.0f, -30.0f, 30.0f};
  const glm::vec3 plainDir = glm::normalize(glm::vec3(0.0f, 0.4f, 1.2f));
  glm::vec3 bestDir = plainDir;
  float bestDistanceM = wantedM, bestScore = -1.0f;
  for (float az : azimuthsDeg) {
    for (float el : elevationsDeg) {
      const float a = glm::radians(az), e = glm::radians(el);
      const glm::vec3 dir(std::sin(a) * std::cos(e), std::sin(e), std::cos(a) * std::cos(e));
      const float hit = venue.firstHitM(centre, dir, wantedM + kMarginM);
      const float distanceM = hit < 0.0f ? wantedM : std::min(wantedM, hit - kMarginM);
      if (distanceM < kMinRoomM) continue;
      const glm::vec3 eye = centre + distanceM * dir;
      int seen = 0;
      for (const glm::vec3& p : sample) {
        const float lengthM = glm::length(p - eye);
        if (lengthM <= kNearPointM || venue.firstHitM(eye, (p - eye) / lengthM, lengthM - kNearPointM) < 0.0f) ++seen;
      }
      const float score = static_cast<float>(seen) / static_cast<float>(sample.size()) + 0.25f * distanceM / wantedM;
      if (score > bestScore + 1e-3f) {  // ties keep the earlier, preferred viewpoint
        bestScore = score;
        bestDir = dir;
        bestDistanceM = distanceM;
      }
    }
  }
  CameraDef cam;
  cam.name = "MVR overview";
  cam.target = glm::round(centre * 100.0f) / 100.0f;
  cam.position = glm::round((centre + bestDistanceM * bestDir) * 100.0f) / 100.0f;
  // 40 degrees frames the rig from the full distance; nearer, widen (at most 75) to keep it.
  const float fitDeg = glm::degrees(2.0f * std::atan(0.5f * 0.6f * extent / bestDistanceM));
  cam.fovYDeg = std::round(std::clamp(fitDeg, 40.0f, 75.0f));
  cam.farM = std::max(100.0f, 4.0f * extent);
  return cam;
}

}  // namespace haze
