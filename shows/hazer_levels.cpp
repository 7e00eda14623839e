#include "shows/hazer_levels.h"

#include <algorithm>

namespace haze {
namespace {

HazerLevel laid(HazerLevel level, const HazerCueDef& d) {
  if (d.output) level.output = *d.output;
  if (d.fan) level.fan = *d.fan;
  return level;
}

bool anyHazerLevels(const Show& show) {
  for (const CueList& l : show.cueLists)
    for (const Cue& c : l.cues)
      if (!c.hazers.empty()) return true;
  return false;
}

}  // namespace

std::map<int, HazerCueDef> trackedHazers(const CueList& list, size_t cueIndex) {
  std::map<int, HazerCueDef> out;
  for (size_t i = 0; i <= cueIndex && i < list.cues.size(); ++i)
    for (const auto& [n, d] : list.cues[i].hazers) {
      HazerCueDef& t = out[n];
      if (d.output) t.output = d.output;
      if (d.fan) t.fan = d.fan;
    }
  return out;
}

HazerSchedule hazerSchedule(const Show& show, const std::vector<HazerCue>& onStage, const std::vector<HazerCue>& gos) {
  HazerSchedule s;
  if (!show.atmosphere.density || !anyHazerLevels(show)) return s;
  const DensitySpec& spec = *show.atmosphere.density;
  const size_t count = spec.hazers.size();
  const double warmup = spec.warmupS;
  std::vector<HazerLevel> start(count);
  for (const HazerCue& c : onStage) {
    if (!c.list) continue;
    for (const auto& [n, d] : trackedHazers(*c.list, c.cueIndex))
      if (n >= 1 && static_cast<size_t>(n) <= count) start[n - 1] = laid(start[n - 1], d);
  }
  for (size_t h = 0; h < count; ++h) s.hold(h, start[h]);
  std::vector<HazerCue> ordered = gos;
  std::stable_sort(ordered.begin(), ordered.end(), [](const HazerCue& a, const HazerCue& b) { return a.goS < b.goS; });
  for (const HazerCue& g : ordered) {
    if (!g.list || g.cueIndex >= g.list->cues.size()) continue;
    const Cue& cue = g.list->cues[g.cueIndex];
    const double at = warmup + std::max(g.goS, 0.0);
    for (const auto& [n, d] : trackedHazers(*g.list, g.cueIndex)) {
      if (n < 1 || static_cast<size_t>(n) > count) continue;
      const size_t h = static_cast<size_t>(n - 1);
      s.fade(h, at, cue.delayS, cue.fadeS, laid(s.at(h, at), d));
    }
  }
  return s;
}

}  // namespace haze
