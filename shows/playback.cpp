// The tracking model of docs/show-format.md as pure functions: tracked states by laying each cue's
// values over the state before it, and the crossfade between two states at a moment after GO
// (delay, then a linear fade of continuous attributes; gobo, prism and shutter switch when the
// fade starts).
#include "shows/playback.h"

#include <algorithm>

#include <glm/common.hpp>

#include "shows/cue_number.h"
#include "shows/effects.h"
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
  if (v.gobo2) a.gobo2 = *v.gobo2;
  if (v.color2) a.color2 = *v.color2;
  if (v.ctoMired) a.ctoMired = *v.ctoMired;
  if (v.gobo2RotationDeg) a.gobo2RotationDeg = *v.gobo2RotationDeg;
  if (v.goboSpinDegS) a.goboSpinDegS = *v.goboSpinDegS;
  if (v.gobo2SpinDegS) a.gobo2SpinDegS = *v.gobo2SpinDegS;
  if (v.prismSpinDegS) a.prismSpinDegS = *v.prismSpinDegS;
  if (v.animation) a.animation = *v.animation;
  if (v.animationRotationDeg) a.animationRotationDeg = *v.animationRotationDeg;
  if (v.animationSpinDegS) a.animationSpinDegS = *v.animationSpinDegS;
  if (v.iris) a.iris = *v.iris;
  for (const auto& [k, cv] : v.cells) {
    if (k < 0) continue;
    if (a.cells.size() <= static_cast<size_t>(k)) a.cells.resize(static_cast<size_t>(k) + 1);
    if (cv.intensity) a.cells[static_cast<size_t>(k)].intensity = *cv.intensity;
    if (cv.color) a.cells[static_cast<size_t>(k)].color = *cv.color;
  }
  if (v.frost) a.frost = *v.frost;
  if (v.gateFocus) a.gateFocus = *v.gateFocus;
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

double curveProgress(FadeCurve curve, double p) {
  if (p <= 0.0 || p >= 1.0) return p;  // -1 (the delay) and the ends stay as they are
  return curve == FadeCurve::SCurve ? p * p * (3.0 - 2.0 * p) : p;
}

namespace {

// Each part of one fixture's fade at its own progress (fadeProgress, -1 during its delay).
struct PartProgress {
  double up, down, position, color, beam;
};

float mix(float a, float b, double p) { return p < 0.0 ? a : p >= 1.0 ? b : lerp(a, b, static_cast<float>(p)); }
glm::vec3 mix(const glm::vec3& a, const glm::vec3& b, double p) {
  return p < 0.0 ? a : p >= 1.0 ? b : a + (b - a) * static_cast<float>(p);
}
// Intensity rises on the up time and falls on the down time.
float mixIntensity(float a, float b, const PartProgress& p) { return mix(a, b, b >= a ? p.up : p.down); }

Attributes blendParts(const Attributes& from, const Attributes& to, const PartProgress& p,
                      std::optional<float> fieldAngleDeg) {
  const double parts[] = {p.up, p.down, p.position, p.color, p.beam};
  if (std::all_of(std::begin(parts), std::end(parts), [](double x) { return x < 0.0; })) return from;
  if (std::all_of(std::begin(parts), std::end(parts), [](double x) { return x >= 1.0; })) return to;
  Attributes a = to;
  a.intensity = mixIntensity(from.intensity, to.intensity, p);
  a.panDeg = mix(from.panDeg, to.panDeg, p.position);
  a.tiltDeg = mix(from.tiltDeg, to.tiltDeg, p.position);
  a.color = mix(from.color, to.color, p.color);
  a.ctoMired = mix(from.ctoMired, to.ctoMired, p.color);
  // A colour wheel's slot switches when the colour's fade starts, as a gobo does with the beam's.
  if (p.color < 0.0) a.color2 = from.color2;
  a.cells.resize(std::max(from.cells.size(), to.cells.size()));
  for (size_t k = 0; k < a.cells.size(); ++k) {
    const CellAttributes c0 = cellAttributes(from, k), c1 = cellAttributes(to, k);
    a.cells[k].intensity = mixIntensity(c0.intensity, c1.intensity, p);
    a.cells[k].color = mix(c0.color, c1.color, p.color);
  }
  // The beam: gobo, prism and shutter switch when the beam's fade starts; the rest fades.
  if (p.beam < 0.0) {
    a.gobo = from.gobo;
    a.gobo2 = from.gobo2;
    a.animation = from.animation;
    a.prism = from.prism;
    a.shutter = from.shutter;
  }
  a.goboRotationDeg = mix(from.goboRotationDeg, to.goboRotationDeg, p.beam);
  a.gobo2RotationDeg = mix(from.gobo2RotationDeg, to.gobo2RotationDeg, p.beam);
  a.goboSpinDegS = mix(from.goboSpinDegS, to.goboSpinDegS, p.beam);
  a.gobo2SpinDegS = mix(from.gobo2SpinDegS, to.gobo2SpinDegS, p.beam);
  a.prismSpinDegS = mix(from.prismSpinDegS, to.prismSpinDegS, p.beam);
  a.animationRotationDeg = mix(from.animationRotationDeg, to.animationRotationDeg, p.beam);
  a.animationSpinDegS = mix(from.animationSpinDegS, to.animationSpinDegS, p.beam);
  a.iris = mix(from.iris, to.iris, p.beam);
  a.frost = mix(from.frost, to.frost, p.beam);
  a.gateFocus = mix(from.gateFocus, to.gateFocus, p.beam);
  a.prismRotationDeg = mix(from.prismRotationDeg, to.prismRotationDeg, p.beam);
  a.bladeRotationDeg = mix(from.bladeRotationDeg, to.bladeRotationDeg, p.beam);
  for (size_t k = 0; k < a.blades.size(); ++k)
    a.blades[k] = p.beam < 0.0 ? from.blades[k] : p.beam >= 1.0 ? to.blades[k]
                                                 : from.blades[k] + (to.blades[k] - from.blades[k]) * static_cast<float>(p.beam);
  // An unset zoom means the profile's field angle: fade through that number when one side is set.
  if (p.beam < 0.0) {
    a.zoomDeg = from.zoomDeg;
  } else if (p.beam < 1.0 && from.zoomDeg != to.zoomDeg) {
    std::optional<float> z0 = from.zoomDeg ? from.zoomDeg : fieldAngleDeg;
    std::optional<float> z1 = to.zoomDeg ? to.zoomDeg : fieldAngleDeg;
    if (z0 && z1) a.zoomDeg = lerp(*z0, *z1, static_cast<float>(p.beam));  // without a profile the zoom snaps
  }
  return a;
}

std::optional<float> fieldAngleOf(const Show& show, const ProfileSet& profiles, int id) {
  if (const FixtureDef* f = show.findFixture(id)) {
    auto p = profiles.find(f->profile);
    if (p != profiles.end() && p->second) return p->second->fieldAngleDeg;
  }
  return std::nullopt;
}

}  // namespace

Attributes blendAttributes(const Attributes& from, const Attributes& to, double progress,
                           std::optional<float> fieldAngleDeg) {
  return blendParts(from, to, PartProgress{progress, progress, progress, progress, progress}, fieldAngleDeg);
}

FixtureTiming fixtureTiming(const Show& show, const Cue& cue, int fixtureId) {
  const CueTimingDef& t = cue.timing;
  double extraDelay = 0.0, extraFade = 0.0;
  if (t.fan)
    if (const GroupDef* g = show.findGroup(t.fan->group))
      for (size_t k = 0; k < g->fixtures.size(); ++k)
        if (g->fixtures[k] == fixtureId) {
          extraDelay = static_cast<double>(k) * t.fan->delayStepS;
          extraFade = static_cast<double>(k) * t.fan->fadeStepS;
          break;
        }
  auto part = [&](const std::optional<PartTiming>& p) {
    return CueTiming{(p && p->delayS ? *p->delayS : cue.delayS) + extraDelay,
                     (p && p->fadeS ? *p->fadeS : cue.fadeS) + extraFade};
  };
  return FixtureTiming{part(t.up), part(t.down), part(t.position), part(t.color), part(t.beam), t.curve};
}

double FixtureTiming::endS() const {
  double end = 0.0;
  for (const CueTiming& p : {up, down, position, color, beam}) end = std::max(end, p.delayS + p.fadeS);
  return end;
}

double cueDurationS(const Show& show, const Cue& cue) {
  if (cue.timing.empty()) return cue.delayS + cue.fadeS;
  double end = fixtureTiming(show, cue, 0).endS();  // a fixture in no fan (ids start at 1)
  for (const FixtureDef& f : show.fixtures) end = std::max(end, fixtureTiming(show, cue, f.id).endS());
  return end;
}

Attributes blendAttributesAt(const Attributes& from, const Attributes& to, const FixtureTiming& t,
                             double secondsSinceGo, std::optional<float> fieldAngleDeg) {
  auto at = [&](const CueTiming& part) { return curveProgress(t.curve, fadeProgress(part, secondsSinceGo)); };
  return blendParts(from, to, PartProgress{at(t.up), at(t.down), at(t.position), at(t.color), at(t.beam)},
                    fieldAngleDeg);
}

static void applyEffects(const Show& show, const ProfileSet& profiles, const Cue& cue, double t, StageState& stage) {
  for (const EffectDef& e : cue.effects) {
    const GroupDef* g = show.findGroup(e.group);
    if (!g) continue;  // loadShow refuses a show whose effect names no group
    const size_t n = g->fixtures.size();
    for (size_t k = 0; k < n; ++k) {
      auto it = stage.find(g->fixtures[k]);
      if (it == stage.end()) continue;
      Attributes& a = it->second;
      // The effect grows in with the fade of the part it moves (0 during the part's delay).
      const FixtureTiming ft = fixtureTiming(show, cue, it->first);
      auto grown = [&](const CueTiming& part) {
        return std::clamp(curveProgress(ft.curve, fadeProgress(part, t)), 0.0, 1.0);
      };
      double tiltWave = 0.0;
      const double w = effectWave(e, k, n, t, &tiltWave);
      const std::string& at = e.attribute;
      auto add = [&](float& v, double amount, double lo, double hi) {
        v = static_cast<float>(std::clamp(static_cast<double>(v) + amount, lo, hi));
      };
      constexpr double kFree = 1e9;
      if (at == "intensity") {
        add(a.intensity, e.size * w * std::max(grown(ft.up), grown(ft.down)), 0.0, 1.0);
      } else if (at == "position") {
        add(a.panDeg, e.size * w * grown(ft.position), -kFree, kFree);
        add(a.tiltDeg, e.size * tiltWave * grown(ft.position), -kFree, kFree);
      } else if (at == "color") {
        // The wave's place among the colours (-1: the first, +1: the last), piecewise linear.
        if (e.colors.size() >= 2) {
          const double u = std::clamp((w + 1.0) * 0.5, 0.0, 1.0) * static_cast<double>(e.colors.size() - 1);
          const size_t i = std::min(static_cast<size_t>(u), e.colors.size() - 2);
          const float f = static_cast<float>(u - static_cast<double>(i));
          const glm::vec3 target = e.colors[i] + (e.colors[i + 1] - e.colors[i]) * f;
          const float depth = static_cast<float>(std::clamp(e.size, 0.0, 1.0) * grown(ft.color));
          a.color = glm::clamp(a.color + (target - a.color) * depth, glm::vec3(0.0f), glm::vec3(1.0f));
        }
      } else if (at == "pan" || at == "tilt") {
        add(at == "pan" ? a.panDeg : a.tiltDeg, e.size * w * grown(ft.position), -kFree, kFree);
      } else {
        const double amount = e.size * w * grown(ft.beam);
        if (at == "zoom") {
          float z = a.zoomDeg ? *a.zoomDeg : fieldAngleOf(show, profiles, it->first).value_or(0.0f);
          if (a.zoomDeg || z > 0.0f) {
            add(z, amount, 0.1, 179.0);
            a.zoomDeg = z;
          }
        } else if (at == "iris") {
          add(a.iris, amount, 0.0, 1.0);
        } else if (at == "frost") {
          add(a.frost, amount, 0.0, 1.0);
        } else if (at == "gobo_rotation") {
          add(a.goboRotationDeg, amount, -kFree, kFree);
        } else if (at == "gobo2_rotation") {
          add(a.gobo2RotationDeg, amount, -kFree, kFree);
        } else if (at == "prism_rotation") {
          add(a.prismRotationDeg, amount, -kFree, kFree);
        } else if (at == "animation_rotation") {
          add(a.animationRotationDeg, amount, -kFree, kFree);
        }
      }
    }
  }
}

StageState blendStatesAt(const Show& show, const ProfileSet& profiles, const StageState& from, const StageState& to,
                         const Cue& cue, double secondsSinceGo) {
  StageState out = to;
  for (auto& [id, a] : out) {
    auto src = from.find(id);
    if (src == from.end()) continue;
    a = blendAttributesAt(src->second, a, fixtureTiming(show, cue, id), secondsSinceGo, fieldAngleOf(show, profiles, id));
  }
  applyEffects(show, profiles, cue, secondsSinceGo, out);
  return out;
}

StageState blendStates(const Show& show, const ProfileSet& profiles, const StageState& from, const StageState& to,
                       double progress) {
  if (progress < 0.0) return from;
  if (progress >= 1.0) return to;
  StageState out = to;
  for (auto& [id, a] : out) {
    auto src = from.find(id);
    if (src == from.end()) continue;
    a = blendAttributes(src->second, a, progress, fieldAngleOf(show, profiles, id));
  }
  return out;
}

StageState stateAt(const Show& show, const ProfileSet& profiles, const CueList& list, size_t cueIndex,
                   double secondsSinceGo) {
  assert(cueIndex < list.cues.size() && "stateAt: cue index past the end of the list; use findCue");
  StageState from = cueIndex == 0 ? defaultState(show) : trackedState(show, profiles, list, cueIndex - 1);
  StageState to = trackedState(show, profiles, list, cueIndex);
  return blendStatesAt(show, profiles, from, to, list.cues[cueIndex], secondsSinceGo);
}

CueValues cueValuesOf(const Attributes& a) {
  CueValues v;
  v.intensity = a.intensity;
  v.panDeg = a.panDeg;
  v.tiltDeg = a.tiltDeg;
  v.color = a.color;
  v.zoomDeg = a.zoomDeg;
  v.gobo = a.gobo;
  v.goboRotationDeg = a.goboRotationDeg;
  // The second wheel and the spins only where they are in, so that a look recorded on a
  // fixture without them reads as before.
  const Attributes neutral;
  if (a.gobo2 != neutral.gobo2) v.gobo2 = a.gobo2;
  if (a.color2 != neutral.color2) v.color2 = a.color2;
  if (a.ctoMired != 0.0f) v.ctoMired = a.ctoMired;
  if (a.gobo2RotationDeg != 0.0f) v.gobo2RotationDeg = a.gobo2RotationDeg;
  if (a.goboSpinDegS != 0.0f) v.goboSpinDegS = a.goboSpinDegS;
  if (a.gobo2SpinDegS != 0.0f) v.gobo2SpinDegS = a.gobo2SpinDegS;
  if (a.prismSpinDegS != 0.0f) v.prismSpinDegS = a.prismSpinDegS;
  if (a.animation != neutral.animation) v.animation = a.animation;
  if (a.animationRotationDeg != 0.0f) v.animationRotationDeg = a.animationRotationDeg;
  if (a.animationSpinDegS != 0.0f) v.animationSpinDegS = a.animationSpinDegS;
  v.iris = a.iris;
  v.frost = a.frost;
  if (a.gateFocus != neutral.gateFocus) v.gateFocus = a.gateFocus;
  v.prism = a.prism;
  v.prismRotationDeg = a.prismRotationDeg;
  v.blades = a.blades;
  v.bladeRotationDeg = a.bladeRotationDeg;
  v.shutter = a.shutter;
  for (size_t k = 0; k < a.cells.size(); ++k)
    v.cells[static_cast<int>(k)] = CellValues{a.cells[k].intensity, a.cells[k].color};
  return v;
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
