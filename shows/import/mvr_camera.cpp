// Places the imported rig's overview camera: candidate viewpoints around the rig's middle,
// each checked with rays against the venue's BVH, the one that sees most of the rig wins.
#include "shows/import/mvr_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace haze {

float firstHitM(const Bvh& venue, const glm::vec3& origin, const glm::vec3& dir, float maxM) {
  const RayHit hit = venue.closestHit(origin, dir, 1e-6f, maxM);
  return hit.hit() ? hit.tM : -1.0f;
}

CameraDef mvrOverviewCamera(const std::vector<glm::vec3>& rigPointsM, const Bvh& venue) {
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
      const float hit = firstHitM(venue, centre, dir, wantedM + kMarginM);
      const float distanceM = hit < 0.0f ? wantedM : std::min(wantedM, hit - kMarginM);
      if (distanceM < kMinRoomM) continue;
      const glm::vec3 eye = centre + distanceM * dir;
      int seen = 0;
      for (const glm::vec3& p : sample) {
        const float lengthM = glm::length(p - eye);
        if (lengthM <= kNearPointM || firstHitM(venue, eye, (p - eye) / lengthM, lengthM - kNearPointM) < 0.0f) ++seen;
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
  // A rig of any size and power: metered, so the first render is neither white nor black.
  cam.exposure = CameraExposureDef{.manual = false, .ev = 0.0f};
  return cam;
}

}  // namespace haze
