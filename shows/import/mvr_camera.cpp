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

namespace {

// The aspect the frame is fitted to: haze render's default 1280 x 720 and a wide GUI viewport.
constexpr float kAspect = 16.0f / 9.0f;
constexpr float kMaxFovDeg = 75.0f;

// Where a camera at `eye` looks so that every rig point is in its picture, and the vertical
// field of view that holds them (at kAspect, 8 % to spare). fits is false when a point is behind
// or beside the camera or the field would be wider than kMaxFovDeg.
struct Framing {
  glm::vec3 forward;
  float fovYDeg = kMaxFovDeg;
  bool fits = false;
};

Framing frameRig(const std::vector<glm::vec3>& points, const glm::vec3& eye, glm::vec3 forward) {
  float tanY = 0.0f;
  // Three turns towards the middle of the points' spread in angle settle it to well under a degree.
  for (int pass = 0; pass < 4; ++pass) {
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    const glm::vec3 up = glm::cross(right, forward);
    float loX = 1e9f, hiX = -1e9f, loY = 1e9f, hiY = -1e9f;
    for (const glm::vec3& p : points) {
      const glm::vec3 d = p - eye;
      const float z = glm::dot(d, forward);
      if (z <= 0.1f * glm::length(d)) return Framing{forward, kMaxFovDeg, false};  // behind or at the side
      const float ax = std::atan(glm::dot(d, right) / z), ay = std::atan(glm::dot(d, up) / z);
      loX = std::min(loX, ax), hiX = std::max(hiX, ax), loY = std::min(loY, ay), hiY = std::max(hiY, ay);
    }
    if (pass == 3) {
      tanY = std::max(std::max(std::tan(-loY), std::tan(hiY)), std::max(std::tan(-loX), std::tan(hiX)) / kAspect);
      break;
    }
    forward = glm::normalize(forward + std::tan(0.5f * (loX + hiX)) * right + std::tan(0.5f * (loY + hiY)) * up);
    forward.y = std::clamp(forward.y, -0.95f, 0.95f);  // never straight up or down: the roll needs +Y
    forward = glm::normalize(forward);
  }
  const float fovDeg = glm::degrees(2.0f * std::atan(1.08f * tanY));
  return Framing{forward, std::min(fovDeg, kMaxFovDeg), fovDeg <= kMaxFovDeg};
}

}  // namespace

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
  // From the audience side first; higher and further aside only when the venue leaves no room
  // in front of the rig for a view that holds it all (a rig filling a closed room).
  const float elevationsDeg[] = {glm::degrees(std::atan(0.4f / 1.2f)), 12.0f, 6.0f, 0.0f, 30.0f, 45.0f};
  const float azimuthsDeg[] = {0.0f, -30.0f, 30.0f, -60.0f, 60.0f};
  const glm::vec3 plainDir = glm::normalize(glm::vec3(0.0f, 0.4f, 1.2f));
  glm::vec3 bestEye = centre + wantedM * plainDir;
  Framing best = frameRig(rigPointsM, bestEye, -plainDir);
  float bestScore = -1.0f;
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
      const Framing framing = frameRig(rigPointsM, eye, -dir);
      // A view that holds the whole rig beats any that does not; then the most points seen.
      const float score = (framing.fits ? 2.0f : 0.0f) + static_cast<float>(seen) / static_cast<float>(sample.size()) +
                          0.25f * distanceM / wantedM;
      if (score > bestScore + 1e-3f) {  // ties keep the earlier, preferred viewpoint
        bestScore = score;
        bestEye = eye;
        best = framing;
      }
    }
  }
  CameraDef cam;
  cam.name = "MVR overview";
  cam.position = glm::round(bestEye * 100.0f) / 100.0f;
  // The target on the fitted line of sight, as far out as the rig's middle.
  const float alongM = std::max(1.0f, glm::dot(centre - bestEye, best.forward));
  cam.target = glm::round((bestEye + alongM * best.forward) * 100.0f) / 100.0f;
  // Rounded up to a whole degree; at least 30 so that an open stage shows some room around it.
  cam.fovYDeg = std::clamp(std::ceil(best.fovYDeg), 30.0f, kMaxFovDeg);
  cam.farM = std::max(100.0f, 4.0f * extent);
  // A rig of any size and power: metered, so the first render is neither white nor black.
  cam.exposure = CameraExposureDef{.manual = false, .ev = 0.0f};
  return cam;
}

}  // namespace haze
