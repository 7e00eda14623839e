#include "shows/scene/exposure.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace haze {

float luminanceOf(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

Metering meterLuminance(std::span<const float> nits, const MeterSettings& s) {
  std::vector<float> v;
  v.reserve(nits.size());
  for (float n : nits)
    if (std::isfinite(n) && n >= 0.0f) v.push_back(n);
  Metering m;
  if (v.empty()) {
    m.ev = s.maxEv;
    return m;
  }
  const size_t k = std::min(v.size() - 1, static_cast<size_t>(s.percentile * static_cast<float>(v.size())));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  m.highlightNits = v[k];
  // A floor far below any lit surface keeps log(0) of black pixels out of the mean.
  constexpr double kFloorNits = 1e-4;
  double logSum = 0.0;
  for (float n : v) logSum += std::log(std::max<double>(n, kFloorNits));
  m.logAverageNits = static_cast<float>(std::exp(logSum / static_cast<double>(v.size())));
  // display = L * 2^ev / kKeyNits, so display d at luminance L needs ev = log2(d * kKeyNits / L).
  const auto evPutting = [](float display, float l) {
    return std::log2(display * kManualKeyNits / std::max(l, 1e-12f));
  };
  const float highlightEv = evPutting(s.highlightDisplay, m.highlightNits);
  const float averageEv = evPutting(s.averageKey, m.logAverageNits);
  m.ev = std::clamp(std::min(highlightEv, averageEv), s.minEv, s.maxEv);
  return m;
}

float exposureEvFor(const ExposureChoice& choice, float meteredEv) {
  return choice.mode == ExposureMode::Manual ? choice.ev : meteredEv + choice.ev;
}

float adaptEv(float currentEv, float targetEv, float dtS, float tauS) {
  if (!std::isfinite(currentEv)) return targetEv;
  if (!(dtS > 0.0f) || !(tauS > 0.0f)) return dtS > 0.0f ? targetEv : currentEv;
  return targetEv + (currentEv - targetEv) * std::exp(-dtS / tauS);
}

}  // namespace haze
