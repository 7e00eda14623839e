// Playbacks (see playbacks.h): one CuePlayer per list, the attributes each list holds stamped with
// a counter that increases with every start (GO, BACK, GOTO, follow, jump), and the merge of the
// lists' stages by those stamps. Follows of different lists fire in the order of their times, so
// the stamps follow the order of the GOs on stage however seldom the clock is read.
#include "shows/playbacks.h"

#include <algorithm>

#include "fixtures/cells.h"
#include "shows/palettes.h"

namespace haze {

namespace {

void copyAttribute(Attributes& to, const Attributes& from, LtpAttribute a, int cell) {
  using A = LtpAttribute;
  switch (a) {
    case A::Pan: to.panDeg = from.panDeg; break;
    case A::Tilt: to.tiltDeg = from.tiltDeg; break;
    case A::Color: to.color = from.color; break;
    case A::Zoom: to.zoomDeg = from.zoomDeg; break;
    case A::Gobo: to.gobo = from.gobo; break;
    case A::GoboRotation: to.goboRotationDeg = from.goboRotationDeg; break;
    case A::Iris: to.iris = from.iris; break;
    case A::Frost: to.frost = from.frost; break;
    case A::GateFocus: to.gateFocus = from.gateFocus; break;
    case A::Prism: to.prism = from.prism; break;
    case A::PrismRotation: to.prismRotationDeg = from.prismRotationDeg; break;
    case A::Blades: to.blades = from.blades; break;
    case A::BladeRotation: to.bladeRotationDeg = from.bladeRotationDeg; break;
    case A::Shutter: to.shutter = from.shutter; break;
    case A::Gobo2: to.gobo2 = from.gobo2; break;
    case A::Gobo2Rotation: to.gobo2RotationDeg = from.gobo2RotationDeg; break;
    case A::GoboSpin: to.goboSpinDegS = from.goboSpinDegS; break;
    case A::Gobo2Spin: to.gobo2SpinDegS = from.gobo2SpinDegS; break;
    case A::PrismSpin: to.prismSpinDegS = from.prismSpinDegS; break;
    case A::Color2: to.color2 = from.color2; break;
    case A::Cto: to.ctoMired = from.ctoMired; break;
    case A::Animation: to.animation = from.animation; break;
    case A::AnimationRotation: to.animationRotationDeg = from.animationRotationDeg; break;
    case A::AnimationSpin: to.animationSpinDegS = from.animationSpinDegS; break;
    case A::CellColor:
    case A::CellIntensity: {
      const size_t k = static_cast<size_t>(cell);
      if (to.cells.size() <= k) to.cells.resize(k + 1);  // new cells at 1 and white, as missing ones are
      const CellAttributes c = cellAttributes(from, k);
      if (a == A::CellColor) to.cells[k].color = c.color;
      else to.cells[k].intensity = c.intensity;
      break;
    }
  }
}

// The attributes an effect moves on each fixture of its group, intensity left out (HTP).
void effectKeys(const Show& show, const EffectDef& e, std::vector<HeldKey>& out) {
  using A = LtpAttribute;
  const GroupDef* g = show.findGroup(e.group);
  if (!g) return;
  std::vector<A> attributes;
  if (e.attribute == "position") attributes = {A::Pan, A::Tilt};
  else if (e.attribute == "pan") attributes = {A::Pan};
  else if (e.attribute == "tilt") attributes = {A::Tilt};
  else if (e.attribute == "zoom") attributes = {A::Zoom};
  else if (e.attribute == "iris") attributes = {A::Iris};
  else if (e.attribute == "frost") attributes = {A::Frost};
  else if (e.attribute == "gobo_rotation") attributes = {A::GoboRotation};
  else if (e.attribute == "gobo2_rotation") attributes = {A::Gobo2Rotation};
  else if (e.attribute == "prism_rotation") attributes = {A::PrismRotation};
  else if (e.attribute == "animation_rotation") attributes = {A::AnimationRotation};
  for (int id : g->fixtures)
    for (A a : attributes) out.emplace_back(id, a, 0);
}

// What a cue asserts when it is gone into: its own values (and its effects' attributes).
void cueKeys(const Show& show, const Cue& cue, bool withEffects, std::vector<HeldKey>& out) {
  for (const auto& [id, v] : cue.values) {
    if (!show.findFixture(id)) continue;  // validation reports unknown ids
    for (const HeldKey& k : heldKeys(id, resolveValues(show, id, v))) out.push_back(k);
  }
  if (withEffects)
    for (const EffectDef& e : cue.effects) effectKeys(show, e, out);
}

}  // namespace

std::vector<HeldKey> heldKeys(int id, const CueValues& v) {
  using A = LtpAttribute;
  std::vector<HeldKey> out;
  auto add = [&](bool set, A a) {
    if (set) out.emplace_back(id, a, 0);
  };
  add(v.panDeg.has_value(), A::Pan);
  add(v.tiltDeg.has_value(), A::Tilt);
  add(v.color.has_value(), A::Color);
  add(v.zoomDeg.has_value(), A::Zoom);
  add(v.gobo.has_value(), A::Gobo);
  add(v.goboRotationDeg.has_value(), A::GoboRotation);
  add(v.iris.has_value(), A::Iris);
  add(v.frost.has_value(), A::Frost);
  add(v.gateFocus.has_value(), A::GateFocus);
  add(v.prism.has_value(), A::Prism);
  add(v.prismRotationDeg.has_value(), A::PrismRotation);
  add(v.blades.has_value(), A::Blades);
  add(v.bladeRotationDeg.has_value(), A::BladeRotation);
  add(v.shutter.has_value(), A::Shutter);
  add(v.gobo2.has_value(), A::Gobo2);
  add(v.gobo2RotationDeg.has_value(), A::Gobo2Rotation);
  add(v.goboSpinDegS.has_value(), A::GoboSpin);
  add(v.gobo2SpinDegS.has_value(), A::Gobo2Spin);
  add(v.prismSpinDegS.has_value(), A::PrismSpin);
  add(v.color2.has_value(), A::Color2);
  add(v.ctoMired.has_value(), A::Cto);
  add(v.animation.has_value(), A::Animation);
  add(v.animationRotationDeg.has_value(), A::AnimationRotation);
  add(v.animationSpinDegS.has_value(), A::AnimationSpin);
  for (const auto& [k, c] : v.cells) {
    if (k < 0) continue;
    if (c.intensity) out.emplace_back(id, A::CellIntensity, k);
    if (c.color) out.emplace_back(id, A::CellColor, k);
  }
  return out;
}

Playbacks::Playbacks(const Show& show, const ProfileSet& profiles) : show_(show), profiles_(profiles) {
  for (const CueList& l : show.cueLists) {
    Slot s;
    s.list = &l;
    s.player = std::make_unique<CuePlayer>(show, profiles, l);
    slots_.push_back(std::move(s));
  }
}

std::optional<size_t> Playbacks::find(const std::string& name) const {
  for (size_t i = 0; i < slots_.size(); ++i)
    if (slots_[i].list->name == name) return i;
  return std::nullopt;
}

void Playbacks::setMaster(size_t i, double level) {
  if (i < slots_.size()) slots_[i].master = std::clamp(level, 0.0, 1.0);
}

std::optional<double> Playbacks::nextFollowAtS() const {
  std::optional<double> next;
  for (const Slot& s : slots_)
    if (auto at = s.player->nextFollowAtS(); at && (!next || *at < *next)) next = at;
  return next;
}

std::optional<size_t> Playbacks::holder(const HeldKey& key) const {
  std::optional<size_t> best;
  uint64_t bestOrder = 0;
  for (size_t i = 0; i < slots_.size(); ++i)
    if (auto it = slots_[i].held.find(key); it != slots_[i].held.end() && it->second > bestOrder) {
      best = i;
      bestOrder = it->second;
    }
  return best;
}

std::vector<size_t> Playbacks::startOrder() const {
  std::vector<size_t> out;
  for (size_t i = 0; i < slots_.size(); ++i)
    if (slots_[i].lastAssert > 0) out.push_back(i);
  std::sort(out.begin(), out.end(), [&](size_t a, size_t b) { return slots_[a].lastAssert < slots_[b].lastAssert; });
  return out;
}

void Playbacks::asserted(size_t i, size_t cue, Assert how, double atS, const StageState* before) {
  Slot& s = slots_[i];
  const CueList& list = *s.list;
  std::vector<HeldKey> keys;
  if (how == Assert::Moves) {
    cueKeys(show_, list.cues[cue], true, keys);
  } else {
    for (size_t c = 0; c <= cue; ++c) cueKeys(show_, list.cues[c], c == cue, keys);
  }
  ++order_;
  for (const HeldKey& k : keys) s.held[k] = order_;
  s.lastAssert = order_;
  s.lastStartS = atS;
  if (!before) return;
  // Take the attributes over from what was on stage: the list's fade starts there.
  StageState& from = s.player->fadeStart();
  for (const auto& [id, attribute, cell] : keys) {
    if (attribute == LtpAttribute::CellIntensity) continue;  // HTP: each list fades its own
    auto f = from.find(id);
    auto b = before->find(id);
    if (f != from.end() && b != before->end()) copyAttribute(f->second, b->second, attribute, cell);
  }
}

void Playbacks::update(double nowS) {
  for (;;) {
    std::optional<size_t> next;
    for (size_t i = 0; i < slots_.size(); ++i) {
      auto at = slots_[i].player->nextFollowAtS();
      if (at && *at <= nowS && (!next || *at < *slots_[*next].player->nextFollowAtS())) next = i;
    }
    if (!next) return;
    CuePlayer& p = *slots_[*next].player;
    const double at = *p.nextFollowAtS();
    const StageState before = merged(at);
    const std::optional<size_t> was = p.currentCue();
    p.update(at);  // this follow, and any that a chain of zero times fires with it
    const std::optional<size_t> now = p.currentCue();
    if (!now || now == was) continue;
    for (size_t c = was ? *was + 1 : 0; c <= *now; ++c)
      asserted(*next, c, Assert::Moves, at, c == *now ? &before : nullptr);
  }
}

bool Playbacks::go(size_t i, double nowS) {
  if (i >= slots_.size()) return false;
  update(nowS);
  const StageState before = merged(nowS);
  if (!slots_[i].player->go(nowS)) return false;
  asserted(i, *slots_[i].player->currentCue(), Assert::Moves, nowS, &before);
  return true;
}

bool Playbacks::back(size_t i, double nowS) {
  if (i >= slots_.size()) return false;
  update(nowS);
  const StageState before = merged(nowS);
  if (!slots_[i].player->back(nowS)) return false;
  asserted(i, *slots_[i].player->currentCue(), Assert::Full, nowS, &before);
  return true;
}

bool Playbacks::gotoCue(size_t i, size_t cueIndex, double nowS) {
  if (i >= slots_.size()) return false;
  update(nowS);
  const StageState before = merged(nowS);
  if (!slots_[i].player->gotoCue(cueIndex, nowS)) return false;
  asserted(i, cueIndex, Assert::Full, nowS, &before);
  return true;
}

bool Playbacks::jumpTo(size_t i, size_t cueIndex, double nowS) {
  if (i >= slots_.size()) return false;
  update(nowS);
  if (!slots_[i].player->jumpTo(cueIndex, nowS)) return false;
  // As if GO had been long ago (CuePlayer::jumpTo): nothing fades.
  asserted(i, cueIndex, Assert::Full, nowS - cueDurationS(show_, slots_[i].list->cues[cueIndex]), nullptr);
  return true;
}

void Playbacks::release(size_t i) {
  if (i >= slots_.size()) return;
  Slot& s = slots_[i];
  s.player = std::make_unique<CuePlayer>(show_, profiles_, *s.list);
  s.held.clear();
  s.lastAssert = 0;
  s.lastStartS.reset();
}

StageState Playbacks::state(double nowS) {
  update(nowS);
  return merged(nowS);
}

StageState Playbacks::merged(double nowS) {
  StageState out = defaultState(show_);
  std::vector<std::optional<StageState>> stages(slots_.size());
  for (size_t i = 0; i < slots_.size(); ++i)
    if (slots_[i].player->currentCue()) stages[i] = slots_[i].player->peek(nowS);

  // Intensity, HTP: the highest master x level of the lists that have played a cue.
  for (auto& [id, a] : out) {
    float level = a.intensity;
    bool any = false;
    for (size_t i = 0; i < slots_.size(); ++i) {
      if (!stages[i]) continue;
      auto it = stages[i]->find(id);
      if (it == stages[i]->end()) continue;
      const float v = static_cast<float>(slots_[i].master) * it->second.intensity;
      level = any ? std::max(level, v) : v;
      any = true;
    }
    a.intensity = level;
  }

  // Everything else: the latest assertion wins; cell intensities: the highest of those that hold it.
  std::map<HeldKey, std::pair<uint64_t, size_t>> latest;
  std::map<HeldKey, float> cellLevels;
  for (size_t i = 0; i < slots_.size(); ++i) {
    if (!stages[i]) continue;
    for (const auto& [key, order] : slots_[i].held) {
      const auto& [id, attribute, cell] = key;
      if (attribute == LtpAttribute::CellIntensity) {
        auto it = stages[i]->find(id);
        if (it == stages[i]->end()) continue;
        const float v = cellAttributes(it->second, static_cast<size_t>(cell)).intensity;
        auto [c, fresh] = cellLevels.try_emplace(key, v);
        if (!fresh) c->second = std::max(c->second, v);
        continue;
      }
      auto [l, fresh] = latest.try_emplace(key, order, i);
      if (!fresh && order > l->second.first) l->second = {order, i};
    }
  }
  for (const auto& [key, by] : latest) {
    const auto& [id, attribute, cell] = key;
    auto to = out.find(id);
    auto from = stages[by.second]->find(id);
    if (to != out.end() && from != stages[by.second]->end()) copyAttribute(to->second, from->second, attribute, cell);
  }
  for (const auto& [key, level] : cellLevels) {
    const auto& [id, attribute, cell] = key;
    auto to = out.find(id);
    if (to == out.end()) continue;
    Attributes one;
    one.cells.resize(static_cast<size_t>(cell) + 1);
    one.cells[static_cast<size_t>(cell)].intensity = level;
    copyAttribute(to->second, one, LtpAttribute::CellIntensity, cell);
  }
  return out;
}

}  // namespace haze
