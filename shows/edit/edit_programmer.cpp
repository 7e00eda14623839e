// Programmer and atmosphere commands. The programmer commands keep, per fixture they touch, the
// entry before and after (absent = not in the programmer), which makes undo, redo and folding a
// drag into one step the same simple swap.
#include <cmath>

#include "shows/edit/edit_commands.h"
#include "shows/edit/edit_util.h"
#include "shows/palettes.h"

namespace haze {

using edit::fixturePlace;
using edit::userError;

namespace {

// The order palettes are applied in (and resolved in, shows/palettes.h).
constexpr PaletteKind kSlotOrder[] = {PaletteKind::All, PaletteKind::Position, PaletteKind::Color, PaletteKind::Beam};

using Entries = std::map<int, std::optional<CueValues>>;

void putEntries(Programmer& p, const Entries& entries) {
  for (const auto& [id, v] : entries) {
    if (v)
      p.values[id] = *v;
    else
      p.values.erase(id);
  }
}

Entries entriesOf(const Programmer& p, const std::vector<int>& ids) {
  Entries e;
  for (int id : ids) {
    auto it = p.values.find(id);
    e[id] = it == p.values.end() ? std::nullopt : std::optional<CueValues>(it->second);
  }
  return e;
}

bool finiteValues(const CueValues& v) {
  for (const auto& f : {v.intensity, v.panDeg, v.tiltDeg, v.zoomDeg, v.goboRotationDeg, v.iris, v.frost, v.gateFocus, v.prismRotationDeg,
                        v.bladeRotationDeg, v.gobo2RotationDeg, v.goboSpinDegS, v.gobo2SpinDegS, v.prismSpinDegS,
                        v.animationRotationDeg, v.animationSpinDegS,
                        v.ctoMired})
    if (f && !std::isfinite(*f)) return false;
  if (v.shutter && !(std::isfinite(v.shutter->rateHz) && std::isfinite(v.shutter->duty))) return false;
  if (v.blades)
    for (const glm::vec2& e : *v.blades)
      if (!std::isfinite(e.x) || !std::isfinite(e.y)) return false;
  return !v.color || (std::isfinite(v.color->x) && std::isfinite(v.color->y) && std::isfinite(v.color->z));
}

class SetProgrammer final : public EditCommand {
 public:
  explicit SetProgrammer(std::map<int, CueValues> values) : values_(std::move(values)) {}
  std::string label() const override {
    return values_.size() == 1 ? "Set fixture " + std::to_string(values_.begin()->first)
                               : "Set " + std::to_string(values_.size()) + " fixtures";
  }
  Status apply(EditTarget& t) override {
    if (values_.empty()) return userError("", "nothing to set; expected at least one fixture");
    if (absorbed_) {  // redo of a folded drag: it ends where the drag's last step did
      putEntries(t.programmer, after_);
      return Ok{};
    }
    std::vector<int> ids;
    for (const auto& [id, v] : values_) {
      if (!t.show.findFixture(id)) return userError(fixturePlace(id), "no fixture with id " + std::to_string(id));
      if (!finiteValues(v)) return userError(fixturePlace(id), "attribute values must be finite numbers");
      ids.push_back(id);
    }
    // Everything is checked before the programmer changes: the palettes exist, are of their
    // slot's kind and give every fixture a value.
    for (const auto& [id, v] : values_)
      for (PaletteKind k : kSlotOrder) {
        const std::string& name = paletteSlot(v.palettes, k);
        if (name.empty()) continue;
        const PaletteDef* pal = t.show.findPalette(name);
        if (!pal) return userError("palette " + name, "no palette is named \"" + name + "\"");
        if (pal->kind != k)
          return userError("palette " + name, std::string("the palette is a ") + paletteKindName(pal->kind) +
                                                  " palette, not a " + paletteKindName(k) + " one");
        if (!paletteValuesFor(t.show, *pal, id))
          return userError("palette " + name, "the palette has no value for fixture " + std::to_string(id) +
                                                  "; nothing was changed");
      }
    before_ = entriesOf(t.programmer, ids);
    for (const auto& [id, v] : values_) {
      CueValues& p = t.programmer.values[id];
      // Palettes first, then the plain values over them (they win, as in a cue).
      for (PaletteKind k : kSlotOrder)
        if (const std::string& name = paletteSlot(v.palettes, k); !name.empty())
          applyPalette(t.show, p, id, *t.show.findPalette(name));
      if (v.intensity) p.intensity = v.intensity;
      if (v.panDeg) p.panDeg = v.panDeg;
      if (v.tiltDeg) p.tiltDeg = v.tiltDeg;
      if (v.zoomDeg) p.zoomDeg = v.zoomDeg;
      if (v.goboRotationDeg) p.goboRotationDeg = v.goboRotationDeg;
      if (v.iris) p.iris = v.iris;
      if (v.color) p.color = v.color;
      if (v.gobo) p.gobo = v.gobo;
      if (v.gobo2) p.gobo2 = v.gobo2;
      if (v.color2) p.color2 = v.color2;
      if (v.ctoMired) p.ctoMired = v.ctoMired;
      if (v.gobo2RotationDeg) p.gobo2RotationDeg = v.gobo2RotationDeg;
      if (v.goboSpinDegS) p.goboSpinDegS = v.goboSpinDegS;
      if (v.gobo2SpinDegS) p.gobo2SpinDegS = v.gobo2SpinDegS;
      if (v.prismSpinDegS) p.prismSpinDegS = v.prismSpinDegS;
      if (v.animation) p.animation = v.animation;
      if (v.animationRotationDeg) p.animationRotationDeg = v.animationRotationDeg;
      if (v.animationSpinDegS) p.animationSpinDegS = v.animationSpinDegS;
      if (v.frost) p.frost = v.frost;
      if (v.gateFocus) p.gateFocus = v.gateFocus;
      if (v.prism) p.prism = v.prism;
      if (v.prismRotationDeg) p.prismRotationDeg = v.prismRotationDeg;
      if (v.blades) p.blades = v.blades;
      if (v.bladeRotationDeg) p.bladeRotationDeg = v.bladeRotationDeg;
      if (v.shutter) p.shutter = v.shutter;
      for (const auto& [k, c] : v.cells) {
        if (c.intensity) p.cells[k].intensity = c.intensity;
        if (c.color) p.cells[k].color = c.color;
      }
    }
    after_ = entriesOf(t.programmer, ids);
    return Ok{};
  }
  void undo(EditTarget& t) override { putEntries(t.programmer, before_); }
  bool absorb(const EditCommand& next) override {
    auto* n = dynamic_cast<const SetProgrammer*>(&next);
    if (!n || n->after_.size() != after_.size()) return false;
    for (const auto& [id, v] : after_)
      if (!n->after_.count(id)) return false;
    after_ = n->after_;
    absorbed_ = true;
    return true;
  }

 private:
  std::map<int, CueValues> values_;
  Entries before_, after_;
  bool absorbed_ = false;
};

class ClearProgrammer final : public EditCommand {
 public:
  explicit ClearProgrammer(std::vector<int> ids) : ids_(std::move(ids)) {}
  std::string label() const override { return ids_.empty() ? "Clear programmer" : "Clear programmer fixtures"; }
  Status apply(EditTarget& t) override {
    std::vector<int> ids = ids_;
    if (ids.empty())
      for (const auto& [id, v] : t.programmer.values) ids.push_back(id);
    before_ = entriesOf(t.programmer, ids);
    for (int id : ids) t.programmer.values.erase(id);
    return Ok{};
  }
  void undo(EditTarget& t) override { putEntries(t.programmer, before_); }

 private:
  std::vector<int> ids_;
  Entries before_;
};

class SetAtmosphere final : public EditCommand {
 public:
  explicit SetAtmosphere(AtmosphereDef a) : after_(std::move(a)) {}
  std::string label() const override { return "Change atmosphere"; }
  Status apply(EditTarget& t) override {
    const AtmosphereDef& a = after_;
    auto nonNegative = [](float x) { return std::isfinite(x) && x >= 0.0f; };
    if (!nonNegative(a.scattering) || !nonNegative(a.absorption))
      return userError("atmosphere", "scattering and absorption must be finite and >= 0 (1/m)");
    if (a.phase != "hazy" && a.phase != "isotropic" && a.phase != "hg")
      return userError("atmosphere", "unknown phase function \"" + a.phase + "\"; expected hazy, isotropic or hg");
    if (!std::isfinite(a.g) || a.g < -0.99f || a.g > 0.99f)
      return userError("atmosphere", "the Henyey-Greenstein g must be in -0.99..0.99");
    for (const glm::vec3& c : {a.ambient, a.background})
      if (!nonNegative(c.x) || !nonNegative(c.y) || !nonNegative(c.z))
        return userError("atmosphere", "ambient and background must be finite and >= 0");
    before_ = std::exchange(t.show.atmosphere, after_);
    return Ok{};
  }
  void undo(EditTarget& t) override { t.show.atmosphere = before_; }
  // A drag on one of the Air tab's fields is one undo step (the GUI asks to merge only while
  // the same widget is being edited).
  bool absorb(const EditCommand& next) override {
    auto* n = dynamic_cast<const SetAtmosphere*>(&next);
    if (!n) return false;
    after_ = n->after_;
    return true;
  }

 private:
  AtmosphereDef after_, before_;
};

}  // namespace

std::unique_ptr<EditCommand> setProgrammer(std::map<int, CueValues> values) { return std::make_unique<SetProgrammer>(std::move(values)); }
std::unique_ptr<EditCommand> clearProgrammer(std::vector<int> ids) { return std::make_unique<ClearProgrammer>(std::move(ids)); }
std::unique_ptr<EditCommand> setAtmosphere(AtmosphereDef atmosphere) { return std::make_unique<SetAtmosphere>(std::move(atmosphere)); }

}  // namespace haze
