#include "renderer/scene/physics.h"

#include <algorithm>
#include <cmath>

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
