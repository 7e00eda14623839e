// The tracking model of docs/show-format.md as pure functions: tracked states by laying each cue's
// values over the state before it, and the crossfade between two states at a moment after GO
// (delay, then a linear fade of continuous attributes; gobo, prism and shutter switch when the
// fade starts).
#include "shows/playback.h"

#include <algorithm>

#include "shows/cue_number.h"
#include "shows/palettes.h"

namespace haze {

namespace {

float lerp(float a, float b, float f) { return a + (b - a) * f; }

}  // namespace

void overlayValues(Attributes& a, const CueValues& v) {
  if (v.intensity) a.intensity = *v.intensity;
  if (v.panDeg) a.panDeg = *v.panDeg;
  if (v.tiltDeg) a.tiltDeg = *v.tiltDeg;
  if (v.color) a.color = *v.color;
  if (v.zoomDeg) a.zoomDeg = *v.zoomDeg;
  if (v.gobo) a.gobo = *v.gobo;
  if (v.goboRotationDeg) a.goboRotationDeg = *v.goboRotationDeg;
  if (v.iris) a.iris = *v.iris;
  for (const auto& [k, cv] : v.cells) {
    if (k < 0) continue;
    if (a.cells.size() <= static_cast<size_t>(k)) a.cells.resize(static_cast<size_t>(k) + 1);
    if (cv.intensity) a.cells[static_cast<size_t>(k)].intensity = *cv.intensity;
    if (cv.color) a.cells[static_cast<size_t>(k)].color = *cv.color;
  }
  if (v.frost) a.frost = *v.frost;
  if (v.prism) a.prism = *v.prism;
  if (v.prismRotationDeg) a.prismRotationDeg = *v.prismRotationDeg;
  if (v.blades) a.blades = *v.blades;
  if (v.bladeRotationDeg) a.bladeRotationDeg = *v.bladeRotationDeg;
  if (v.shutter) a.shutter = *v.shutter;
}

StageState defaultState(const Show& show) {
  StageState s;
  for (const FixtureDef& f : show.fixtures) s[f.id] = Attributes{};
  return s;
}

StageState trackedState(const Show& show, const ProfileSet& /*profiles*/, const CueList& list, size_t cueIndex) {
  assert(cueIndex < list.cues.size() && "trackedState: cue index past the end of the list; use findCue");
  StageState s = defaultState(show);
  for (size_t i = 0; i <= cueIndex && i < list.cues.size(); ++i)
    for (const auto& [id, v] : list.cues[i].values) {
      auto it = s.find(id);
      // Palettes resolve here, as the cue plays, so a changed palette reaches every cue using it.
      if (it != s.end()) overlayValues(it->second, resolveValues(show, id, v));  // unknown ids: validation reports them
    }
  return s;
}

double fadeProgress(const CueTiming& t, double secondsSinceGo) {
  if (secondsSinceGo < t.delayS) return -1.0;
  if (t.fadeS <= 0.0) return 1.0;
  return std::clamp((secondsSinceGo - t.delayS) / t.fadeS, 0.0, 1.0);
}

Attributes blendAttributes(const Attributes& from, const Attributes& to, double progress,
                           std::optional<float> fieldAngleDeg) {
  if (progress < 0.0) return from;
  if (progress >= 1.0) return to;
  float f = static_cast<float>(progress);
  Attributes a = to;  // discrete attributes (gobo) already switched: the fade has started
  a.intensity = lerp(from.intensity, to.intensity, f);
  a.panDeg = lerp(from.panDeg, to.panDeg, f);
  a.tiltDeg = lerp(from.tiltDeg, to.tiltDeg, f);
  a.color = from.color + (to.color - from.color) * f;
  a.goboRotationDeg = lerp(from.goboRotationDeg, to.goboRotationDeg, f);
  a.iris = lerp(from.iris, to.iris, f);
  a.cells.resize(std::max(from.cells.size(), to.cells.size()));
  for (size_t k = 0; k < a.cells.size(); ++k) {
    const CellAttributes c0 = cellAttributes(from, k), c1 = cellAttributes(to, k);
    a.cells[k].intensity = lerp(c0.intensity, c1.intensity, f);
    a.cells[k].color = c0.color + (c1.color - c0.color) * f;
  }
  // Optics: prism and shutter switched with the gobo (a = to); the rest fades.
  a.frost = lerp(from.frost, to.frost, f);
  a.prismRotationDeg = lerp(from.prismRotationDeg, to.prismRotationDeg, f);
  a.bladeRotationDeg = lerp(from.bladeRotationDeg, to.bladeRotationDeg, f);
  for (size_t k = 0; k < a.blades.size(); ++k) a.blades[k] = from.blades[k] + (to.blades[k] - from.blades[k]) * f;
  // An unset zoom means the profile's field angle: fade through that number when one side is set.
  if (from.zoomDeg != to.zoomDeg) {
    std::optional<float> z0 = from.zoomDeg ? from.zoomDeg : fieldAngleDeg;
    std::optional<float> z1 = to.zoomDeg ? to.zoomDeg : fieldAngleDeg;
    if (z0 && z1) a.zoomDeg = lerp(*z0, *z1, f);  // without a profile the zoom snaps with the gobo
  }
  return a;
}

StageState blendStates(const Show& show, const ProfileSet& profiles, const StageState& from, const StageState& to,
                       double progress) {
  if (progress < 0.0) return from;
  if (progress >= 1.0) return to;
  StageState out = to;
  for (auto& [id, a] : out) {
    auto src = from.find(id);
    if (src == from.end()) continue;
    std::optional<float> field;
    if (const FixtureDef* f = show.findFixture(id)) {
      auto p = profiles.find(f->profile);
      if (p != profiles.end() && p->second) field = p->second->fieldAngleDeg;
    }
    a = blendAttributes(src->second, a, progress, field);
  }
  return out;
}

StageState stateAt(const Show& show, const ProfileSet& profiles, const CueList& list, size_t cueIndex,
                   double secondsSinceGo) {
  assert(cueIndex < list.cues.size() && "stateAt: cue index past the end of the list; use findCue");
  StageState from = cueIndex == 0 ? defaultState(show) : trackedState(show, profiles, list, cueIndex - 1);
  StageState to = trackedState(show, profiles, list, cueIndex);
  const Cue& cue = list.cues[cueIndex];
  return blendStates(show, profiles, from, to, fadeProgress(CueTiming{cue.delayS, cue.fadeS}, secondsSinceGo));
}

Result<size_t> findCue(const CueList& list, const std::string& number) {
  if (isCueNumber(number))
    for (size_t i = 0; i < list.cues.size(); ++i)
      if (isCueNumber(list.cues[i].number) && compareCueNumbers(list.cues[i].number, number) == 0) return i;
  std::string numbers;
  for (const Cue& c : list.cues) numbers += (numbers.empty() ? "" : ", ") + c.number;
  return Error{"", "", "cue list \"" + list.name + "\" has no cue \"" + number + "\"; its cues are: " +
                           (numbers.empty() ? "(none)" : numbers)};
}

}  // namespace haze
