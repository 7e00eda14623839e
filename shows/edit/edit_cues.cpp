// Cue commands: record and update from the programmer (tracking: a cue stores only what changes
// against the tracked state before it), delete, renumber, label and times. Undo data is the old
// cue itself or the one field replaced, so undo restores the list exactly.
#include <cassert>
#include <cmath>

#include "fixtures/cells.h"
#include "shows/cue_number.h"
#include "shows/edit/edit_commands.h"
#include "shows/edit/edit_cue_number.h"
#include "shows/edit/edit_util.h"
#include "shows/palettes.h"

namespace haze {

using edit::cuePlace;
using edit::listIndex;
using edit::listPlace;
using edit::userError;

namespace edit {

Result<CueAt> findCueAt(const Show& show, const std::string& list, const std::string& number) {
  auto l = listIndex(show, list);
  if (!l) return userError(listPlace(list), "the show has no " + listPlace(list));
  Result<size_t> c = findCue(show.cueLists[*l], number);
  if (!c) return userError(cuePlace(list, number), c.error().message);
  return CueAt{*l, *c};
}

}  // namespace edit

namespace {

// The state the programmer is compared with for a cue at `index`: the tracked state of the cue
// before it, or the defaults ahead of the first cue.
StageState stateBefore(const Show& show, const ProfileSet& profiles, const CueList& list, size_t index) {
  return index == 0 ? defaultState(show) : trackedState(show, profiles, list, index - 1);
}

// For each attribute the programmer sets: `same` when it equals the state before, else `differs`.
template <typename Same, typename Differs>
void compareField(const Attributes& before, const CueValues& p, Same same, Differs differs) {
  auto check = [&](auto member, auto value, bool equal) {
    if (!value) return;
    if (equal)
      same(member);
    else
      differs(member);
  };
  check(&CueValues::intensity, p.intensity, p.intensity && *p.intensity == before.intensity);
  check(&CueValues::panDeg, p.panDeg, p.panDeg && *p.panDeg == before.panDeg);
  check(&CueValues::tiltDeg, p.tiltDeg, p.tiltDeg && *p.tiltDeg == before.tiltDeg);
  check(&CueValues::zoomDeg, p.zoomDeg, p.zoomDeg && before.zoomDeg == p.zoomDeg);
  check(&CueValues::goboRotationDeg, p.goboRotationDeg, p.goboRotationDeg && *p.goboRotationDeg == before.goboRotationDeg);
  check(&CueValues::iris, p.iris, p.iris && *p.iris == before.iris);
  check(&CueValues::color, p.color, p.color && *p.color == before.color);
  check(&CueValues::gobo, p.gobo, p.gobo && *p.gobo == before.gobo);
  check(&CueValues::gobo2, p.gobo2, p.gobo2 && *p.gobo2 == before.gobo2);
  check(&CueValues::color2, p.color2, p.color2 && *p.color2 == before.color2);
  check(&CueValues::ctoMired, p.ctoMired, p.ctoMired && *p.ctoMired == before.ctoMired);
  check(&CueValues::gobo2RotationDeg, p.gobo2RotationDeg, p.gobo2RotationDeg && *p.gobo2RotationDeg == before.gobo2RotationDeg);
  check(&CueValues::goboSpinDegS, p.goboSpinDegS, p.goboSpinDegS && *p.goboSpinDegS == before.goboSpinDegS);
  check(&CueValues::gobo2SpinDegS, p.gobo2SpinDegS, p.gobo2SpinDegS && *p.gobo2SpinDegS == before.gobo2SpinDegS);
  check(&CueValues::prismSpinDegS, p.prismSpinDegS, p.prismSpinDegS && *p.prismSpinDegS == before.prismSpinDegS);
  check(&CueValues::animation, p.animation, p.animation && *p.animation == before.animation);
  check(&CueValues::animationRotationDeg, p.animationRotationDeg,
        p.animationRotationDeg && *p.animationRotationDeg == before.animationRotationDeg);
  check(&CueValues::animationSpinDegS, p.animationSpinDegS, p.animationSpinDegS && *p.animationSpinDegS == before.animationSpinDegS);
  check(&CueValues::frost, p.frost, p.frost && *p.frost == before.frost);
  check(&CueValues::gateFocus, p.gateFocus, p.gateFocus && *p.gateFocus == before.gateFocus);
  check(&CueValues::prism, p.prism, p.prism && *p.prism == before.prism);
  check(&CueValues::prismRotationDeg, p.prismRotationDeg, p.prismRotationDeg && *p.prismRotationDeg == before.prismRotationDeg);
  check(&CueValues::blades, p.blades, p.blades && *p.blades == before.blades);
  check(&CueValues::bladeRotationDeg, p.bladeRotationDeg, p.bladeRotationDeg && *p.bladeRotationDeg == before.bladeRotationDeg);
  check(&CueValues::shutter, p.shutter, p.shutter && *p.shutter == before.shutter);
}

// Folds one fixture's programmer entry `p` into its values in `cue`. Palette references are
// always taken (they are what the cue follows when the palette changes; the plain values they
// replace leave the cue). A plain value that differs from `before` is set; one equal to it is
// removed from the cue (tracking then gives the same value), unless a palette of the cue would
// give that attribute instead.
void fold(const Show& show, int id, const Attributes& before, const CueValues& p, CueValues& cue) {
  for (PaletteKind k : {PaletteKind::All, PaletteKind::Position, PaletteKind::Color, PaletteKind::Beam})
    if (const std::string& name = paletteSlot(p.palettes, k); !name.empty())
      if (const PaletteDef* pal = show.findPalette(name)) applyPalette(show, cue, id, *pal);
  CueValues refsOnly;
  refsOnly.palettes = cue.palettes;
  const CueValues fromPalettes = resolveValues(show, id, refsOnly);
  compareField(
      before, p,
      [&](auto member) {
        if (fromPalettes.*member)
          cue.*member = p.*member;
        else
          (cue.*member).reset();
      },
      [&](auto member) { cue.*member = p.*member; });
  // Cells per cell and value (docs/cells.md), as the fixture's own values.
  for (const auto& [k, pc] : p.cells) {
    if (k < 0) continue;
    const CellAttributes b = cellAttributes(before, static_cast<size_t>(k));
    const auto under = fromPalettes.cells.find(k);
    const bool palIntensity = under != fromPalettes.cells.end() && under->second.intensity;
    const bool palColor = under != fromPalettes.cells.end() && under->second.color;
    CellValues& c = cue.cells[k];
    if (pc.intensity) c.intensity = *pc.intensity == b.intensity && !palIntensity ? std::nullopt : pc.intensity;
    if (pc.color) c.color = *pc.color == b.color && !palColor ? std::nullopt : pc.color;
    if (!c.intensity && !c.color) cue.cells.erase(k);
  }
}

class RecordCue final : public EditCommand {
 public:
  explicit RecordCue(CueRecord r) : r_(std::move(r)) {}
  std::string label() const override { return "Record cue " + number_; }
  Status apply(EditTarget& t) override {
    if (!r_.number.empty() && !isCueNumber(r_.number))
      return userError(listPlace(r_.list), "\"" + r_.number + "\" is not a cue number; expected digits with an optional decimal part");
    auto l = listIndex(t.show, r_.list);
    CueList scratch;
    scratch.name = r_.list.empty() ? "Main" : r_.list;
    const CueList& list = l ? t.show.cueLists[*l] : scratch;
    size_t at = 0;
    std::optional<std::string> prev, next;
    if (!r_.after.empty()) {
      Result<size_t> a = findCue(list, r_.after);
      if (!a) return userError(cuePlace(r_.list, r_.after), a.error().message);
      at = *a + 1;
      prev = list.cues[*a].number;
    }
    if (at < list.cues.size()) next = list.cues[at].number;
    std::string number = r_.number;
    if (number.empty()) {
      Result<std::string> n = cueNumberBetween(prev, next);
      if (!n) return userError(listPlace(r_.list), n.error().message);
      number = *n;
    } else if ((prev && compareCueNumbers(*prev, number) >= 0) || (next && compareCueNumbers(number, *next) >= 0)) {
      return userError(listPlace(r_.list), "cue number " + number + " does not fit " +
                                               (prev ? "after cue " + *prev : std::string("at the start")) +
                                               (next ? " and before cue " + *next : std::string()) +
                                               "; expected a number between its neighbours");
    }
    StageState before = stateBefore(t.show, t.profiles, list, at);
    Cue cue;
    cue.number = number;
    cue.label = r_.label;
    cue.fadeS = t.show.defaultFadeS;  // the show's default cue time (edit_defaults.h)
    for (const auto& [id, p] : t.programmer.values) {
      auto b = before.find(id);
      if (b == before.end()) continue;  // not a fixture of the show
      CueValues v;
      fold(t.show, id, b->second, p, v);
      if (!(v == CueValues{})) cue.values[id] = v;
    }
    createdList_ = !l;
    if (createdList_) t.show.cueLists.push_back(scratch);
    listAt_ = l ? *l : t.show.cueLists.size() - 1;
    auto& cues = t.show.cueLists[listAt_].cues;
    cues.insert(cues.begin() + static_cast<long>(at), std::move(cue));
    cueAt_ = at;
    number_ = number;
    return Ok{};
  }
  void undo(EditTarget& t) override {
    auto& cues = t.show.cueLists[listAt_].cues;
    assert(cueAt_ < cues.size() && cues[cueAt_].number == number_ && "RecordCue::undo: the cue moved");
    cues.erase(cues.begin() + static_cast<long>(cueAt_));
    if (createdList_) t.show.cueLists.erase(t.show.cueLists.begin() + static_cast<long>(listAt_));
  }

 private:
  CueRecord r_;
  std::string number_;
  bool createdList_ = false;
  size_t listAt_ = 0, cueAt_ = 0;
};

// Commands that change one existing cue keep the whole old cue: cues are small, and it makes undo
// exact whatever changed.
class ChangeCue : public EditCommand {
 public:
  ChangeCue(std::string list, std::string number) : list_(std::move(list)), number_(std::move(number)) {}
  Status apply(EditTarget& t) final {
    Result<edit::CueAt> at = edit::findCueAt(t.show, list_, number_);
    if (!at) return at.error();
    Cue& cue = t.show.cueLists[at->list].cues[at->cue];
    Cue old = cue;
    Status s = change(t, t.show.cueLists[at->list], at->cue, cue);
    if (!s) return s;
    at_ = *at;
    old_ = std::move(old);
    return Ok{};
  }
  void undo(EditTarget& t) final { t.show.cueLists[at_.list].cues[at_.cue] = old_; }

 protected:
  // Checks, then changes `cue` (at `index` in `list`); on an error it has changed nothing.
  virtual Status change(EditTarget& t, const CueList& list, size_t index, Cue& cue) = 0;
  std::string list_, number_;

 private:
  edit::CueAt at_;
  Cue old_;
};

class UpdateCue final : public ChangeCue {
 public:
  using ChangeCue::ChangeCue;
  std::string label() const override { return "Update cue " + number_; }

 protected:
  Status change(EditTarget& t, const CueList& list, size_t index, Cue& cue) override {
    StageState before = stateBefore(t.show, t.profiles, list, index);
    for (const auto& [id, p] : t.programmer.values) {
      auto b = before.find(id);
      if (b == before.end()) continue;
      CueValues v = cue.values.count(id) ? cue.values.at(id) : CueValues{};
      fold(t.show, id, b->second, p, v);
      if (v == CueValues{})
        cue.values.erase(id);
      else
        cue.values[id] = v;
    }
    return Ok{};
  }
};

class LabelCue final : public ChangeCue {
 public:
  LabelCue(std::string list, std::string number, std::string label) : ChangeCue(std::move(list), std::move(number)), label_(std::move(label)) {}
  std::string label() const override { return "Label cue " + number_; }

 protected:
  Status change(EditTarget&, const CueList&, size_t, Cue& cue) override {
    cue.label = label_;
    return Ok{};
  }

 private:
  std::string label_;
};

class SetCueTimes final : public ChangeCue {
 public:
  SetCueTimes(std::string list, std::string number, CueTimes times) : ChangeCue(std::move(list), std::move(number)), times_(times) {}
  std::string label() const override { return "Set times of cue " + number_; }

 protected:
  Status change(EditTarget&, const CueList&, size_t, Cue& cue) override {
    auto ok = [](double s) { return std::isfinite(s) && s >= 0.0; };
    if (!ok(times_.fadeS) || !ok(times_.delayS) || (times_.followS && !ok(*times_.followS)))
      return userError(cuePlace(list_, number_), "fade, delay and follow must be finite numbers of seconds >= 0");
    cue.fadeS = times_.fadeS;
    cue.delayS = times_.delayS;
    cue.followS = times_.followS;
    return Ok{};
  }

 private:
  CueTimes times_;
};

class DeleteCue final : public EditCommand {
 public:
  DeleteCue(std::string list, std::string number) : list_(std::move(list)), number_(std::move(number)) {}
  std::string label() const override { return "Delete cue " + number_; }
  Status apply(EditTarget& t) override {
    Result<edit::CueAt> at = edit::findCueAt(t.show, list_, number_);
    if (!at) return at.error();
    at_ = *at;
    auto& cues = t.show.cueLists[at_.list].cues;
    old_ = std::move(cues[at_.cue]);
    cues.erase(cues.begin() + static_cast<long>(at_.cue));
    return Ok{};
  }
  void undo(EditTarget& t) override {
    auto& cues = t.show.cueLists[at_.list].cues;
    cues.insert(cues.begin() + static_cast<long>(at_.cue), old_);
  }

 private:
  std::string list_, number_;
  edit::CueAt at_;
  Cue old_;
};

class RenumberCue final : public EditCommand {
 public:
  RenumberCue(std::string list, std::string number, std::string newNumber)
      : list_(std::move(list)), number_(std::move(number)), newNumber_(std::move(newNumber)) {}
  std::string label() const override { return "Renumber cue " + number_ + " to " + newNumber_; }
  Status apply(EditTarget& t) override {
    Result<edit::CueAt> at = edit::findCueAt(t.show, list_, number_);
    if (!at) return at.error();
    if (!isCueNumber(newNumber_))
      return userError(cuePlace(list_, number_), "\"" + newNumber_ + "\" is not a cue number; expected digits with an optional decimal part");
    auto& cues = t.show.cueLists[at->list].cues;
    for (size_t i = 0; i < cues.size(); ++i)
      if (i != at->cue && compareCueNumbers(cues[i].number, newNumber_) == 0)
        return userError(cuePlace(list_, number_), "cue " + newNumber_ + " already exists in " + listPlace(list_) + "; expected an unused number");
    at_ = *at;
    Cue cue = std::move(cues[at_.cue]);
    cues.erase(cues.begin() + static_cast<long>(at_.cue));
    oldNumber_ = std::exchange(cue.number, newNumber_);
    newIndex_ = 0;
    while (newIndex_ < cues.size() && compareCueNumbers(cues[newIndex_].number, newNumber_) < 0) ++newIndex_;
    cues.insert(cues.begin() + static_cast<long>(newIndex_), std::move(cue));
    return Ok{};
  }
  void undo(EditTarget& t) override {
    auto& cues = t.show.cueLists[at_.list].cues;
    Cue cue = std::move(cues[newIndex_]);
    cues.erase(cues.begin() + static_cast<long>(newIndex_));
    cue.number = oldNumber_;
    cues.insert(cues.begin() + static_cast<long>(at_.cue), std::move(cue));
  }

 private:
  std::string list_, number_, newNumber_, oldNumber_;
  edit::CueAt at_;
  size_t newIndex_ = 0;
};

}  // namespace

std::unique_ptr<EditCommand> recordCue(CueRecord record) { return std::make_unique<RecordCue>(std::move(record)); }

namespace {
// RecordCue run against a programmer of its own: one rule for what a new cue keeps.
class RecordLook final : public EditCommand {
 public:
  RecordLook(CueRecord record, std::map<int, CueValues> look) : inner_(std::move(record)) {
    look_.values = std::move(look);
  }
  std::string label() const override { return inner_.label() + " from the live look"; }
  Status apply(EditTarget& t) override {
    EditTarget own{t.show, look_, t.profiles};
    return inner_.apply(own);
  }
  void undo(EditTarget& t) override {
    EditTarget own{t.show, look_, t.profiles};
    inner_.undo(own);
  }

 private:
  RecordCue inner_;
  Programmer look_;
};
}  // namespace

std::unique_ptr<EditCommand> recordLook(CueRecord record, std::map<int, CueValues> look) {
  return std::make_unique<RecordLook>(std::move(record), std::move(look));
}
std::unique_ptr<EditCommand> updateCue(std::string list, std::string number) {
  return std::make_unique<UpdateCue>(std::move(list), std::move(number));
}
std::unique_ptr<EditCommand> deleteCue(std::string list, std::string number) {
  return std::make_unique<DeleteCue>(std::move(list), std::move(number));
}
std::unique_ptr<EditCommand> renumberCue(std::string list, std::string number, std::string newNumber) {
  return std::make_unique<RenumberCue>(std::move(list), std::move(number), std::move(newNumber));
}
std::unique_ptr<EditCommand> labelCue(std::string list, std::string number, std::string label) {
  return std::make_unique<LabelCue>(std::move(list), std::move(number), std::move(label));
}
std::unique_ptr<EditCommand> setCueTimes(std::string list, std::string number, CueTimes times) {
  return std::make_unique<SetCueTimes>(std::move(list), std::move(number), times);
}

}  // namespace haze
