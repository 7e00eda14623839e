#include "atmosphere/hazer_schedule.h"

#include <algorithm>

namespace haze {

HazerLevel HazerSchedule::at(size_t hazer, double t) const {
  if (hazer >= keys_.size() || keys_[hazer].empty()) return {};
  const std::vector<HazerKey>& k = keys_[hazer];
  if (t <= k.front().timeS) return k.front().level;
  if (t >= k.back().timeS) return k.back().level;
  const auto after = std::upper_bound(k.begin(), k.end(), t, [](double v, const HazerKey& key) { return v < key.timeS; });
  const HazerKey& b = *after;
  const HazerKey& a = *(after - 1);
  const double span = b.timeS - a.timeS;
  const float f = span > 0.0 ? static_cast<float>((t - a.timeS) / span) : 1.0f;
  return {a.level.output + (b.level.output - a.level.output) * f, a.level.fan + (b.level.fan - a.level.fan) * f};
}

bool HazerSchedule::fansChange() const {
  for (const std::vector<HazerKey>& k : keys_)
    for (size_t i = 1; i < k.size(); ++i)
      if (k[i].level.fan != k[0].level.fan) return true;
  return false;
}

void HazerSchedule::hold(size_t hazer, HazerLevel level) {
  if (keys_.size() <= hazer) keys_.resize(hazer + 1);
  keys_[hazer] = {HazerKey{0.0, level}};
}

void HazerSchedule::fade(size_t hazer, double goS, double delayS, double fadeS, HazerLevel target) {
  const HazerLevel now = at(hazer, goS);
  if (keys_.size() <= hazer) keys_.resize(hazer + 1);
  std::vector<HazerKey>& k = keys_[hazer];
  k.erase(std::upper_bound(k.begin(), k.end(), goS, [](double v, const HazerKey& key) { return v < key.timeS; }), k.end());
  const double start = goS + std::max(delayS, 0.0);
  k.push_back({goS, now});
  if (start > goS) k.push_back({start, now});
  // A fade of 0 jumps: the target a hair after the start, so `at` is never ambiguous.
  k.push_back({start + std::max(fadeS, 1e-9), target});
}

}  // namespace haze
