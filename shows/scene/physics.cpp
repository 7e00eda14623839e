#include "shows/scene/physics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace haze {

float phaseFunction(const MediumState& m, float cosA) {
  switch (m.phase) {
    case Phase::Isotropic:
      return 1.0f / (4.0f * kPi);
    case Phase::HenyeyGreenstein: {
      const float g = m.g;
      const float denom = 1.0f + g * g - 2.0f * g * cosA;
      return (1.0f - g * g) / (4.0f * kPi * denom * std::sqrt(denom));
    }
    case Phase::Hazy:
    default: {
      // cos^2(a/2) = (1 + cos a) / 2, so cos^6(a/2) = ((1 + cos a) / 2)^3.
      const float c2 = 0.5f * (1.0f + cosA);
      return (1.0f + 9.0f * c2 * c2 * c2) / (13.0f * kPi);
    }
  }
}

glm::vec3 beamIntensityTowards(const BeamState& beam, const glm::vec3& x) {
  const glm::vec3 d = x - beam.pose.lensPosition;
  const float len = glm::length(d);
  if (len <= 0.0f) return glm::vec3(0.0f);
  const glm::vec3 w = d / len;
  const float cz = std::clamp(glm::dot(w, beam.pose.zb), -1.0f, 1.0f);
  const float theta = std::acos(cz);
  const float phi = std::atan2(glm::dot(w, beam.pose.yb), glm::dot(w, beam.pose.xb));
  return beam.optics.intensityCd(theta, phi);
}

}  // namespace haze

namespace haze {

glm::vec3 sunDirection(float azimuthDeg, float elevationDeg) {
  const float az = azimuthDeg * kPi / 180.0f, el = elevationDeg * kPi / 180.0f;
  const glm::vec3 towardsSun(std::sin(az) * std::cos(el), std::sin(el), -std::cos(az) * std::cos(el));
  return -glm::normalize(towardsSun);
}

float sunPathInBox(const glm::vec3& x, const glm::vec3& direction, const glm::vec3& lo, const glm::vec3& hi) {
  for (int a = 0; a < 3; ++a)
    if (x[a] < lo[a] || x[a] > hi[a]) return 0.0f;
  // Inside: the exit distance along u = -direction is the nearest of the far slabs.
  float exit = std::numeric_limits<float>::infinity();
  for (int a = 0; a < 3; ++a) {
    const float u = -direction[a];
    if (u > 0.0f) exit = std::min(exit, (hi[a] - x[a]) / u);
    if (u < 0.0f) exit = std::min(exit, (lo[a] - x[a]) / u);
  }
  return std::isfinite(exit) ? std::max(exit, 0.0f) : 0.0f;
}

}  // namespace haze
