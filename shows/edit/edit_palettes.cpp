// Group and palette commands: recording a palette or a group from the GUI, updating a palette
// from the programmer, deleting either. Each keeps the groups, palettes and programmer it
// started from, so undo restores them exactly (they are small next to the cue lists).
#include "shows/edit/edit_commands.h"
#include "shows/edit/edit_util.h"
#include "shows/palettes.h"

namespace haze {

using edit::userError;

std::string paletteKindAttributes(PaletteKind kind) {
  switch (kind) {
    case PaletteKind::Position: return "pan, tilt";
    case PaletteKind::Color: return "colour, cell colours";
    case PaletteKind::Beam: return "zoom, gobo, iris, frost, prism, blades, shutter";
    case PaletteKind::All: break;
  }
  return "any attribute";
}

PaletteKind paletteKindOfProgrammer(const Show& show, const Programmer& programmer) {
  bool position = false, color = false, beam = false;
  for (const auto& [id, v] : programmer.values) {
    const CueValues r = resolveValues(show, id, v);
    position = position || hasValues(valuesOfKind(PaletteKind::Position, r));
    color = color || hasValues(valuesOfKind(PaletteKind::Color, r));
    beam = beam || hasValues(valuesOfKind(PaletteKind::Beam, r));
  }
  if (position + color + beam != 1) return PaletteKind::All;
  return position ? PaletteKind::Position : color ? PaletteKind::Color : PaletteKind::Beam;
}

namespace {

std::string inQuotes(const std::string& name) { return "\"" + name + "\""; }

std::string joined(const std::vector<std::string>& items) {
  std::string s;
  for (size_t k = 0; k < items.size() && k < 6; ++k) s += (k ? ", " : "") + items[k];
  if (items.size() > 6) s += " and " + std::to_string(items.size() - 6) + " more";
  return s;
}

// Keeps what undo needs: the show's groups and palettes and the programmer before the change.
class GroupsAndPalettesEdit : public EditCommand {
 public:
  Status apply(EditTarget& t) final {
    std::vector<GroupDef> groups = t.show.groups;
    std::vector<PaletteDef> palettes = t.show.palettes;
    Programmer programmer = t.programmer;
    Status s = change(t);
    if (!s) return s;
    groups_ = std::move(groups);
    palettes_ = std::move(palettes);
    programmer_ = std::move(programmer);
    return Ok{};
  }
  void undo(EditTarget& t) final {
    t.show.groups = groups_;
    t.show.palettes = palettes_;
    t.programmer = programmer_;
  }

 protected:
  // Checks, then changes; on an error it has changed nothing.
  virtual Status change(EditTarget& t) = 0;

 private:
  std::vector<GroupDef> groups_;
  std::vector<PaletteDef> palettes_;
  Programmer programmer_;
};

// The programmer's values of `kind` per fixture (palettes resolved), fixtures without any left out.
std::map<int, CueValues> programmerValues(const EditTarget& t, PaletteKind kind) {
  std::map<int, CueValues> out;
  for (const auto& [id, v] : t.programmer.values) {
    if (!t.show.findFixture(id)) continue;
    CueValues k = valuesOfKind(kind, resolveValues(t.show, id, v));
    if (hasValues(k)) out[id] = std::move(k);
  }
  return out;
}

Error nothingOfKind(PaletteKind kind, const std::string& name, const Programmer& p) {
  if (p.values.empty())
    return userError("palette " + name, "the programmer is empty: nothing to put in the palette; set values first (\"1 thru 4 pan 30\")");
  return userError("palette " + name, std::string("the programmer holds no ") +
                                          (kind == PaletteKind::All ? "values" : std::string(paletteKindName(kind)) +
                                                                                     " values (" + paletteKindAttributes(kind) + ")") +
                                          "; nothing was changed");
}

// After recording or updating a palette the programmer's fixtures refer to it, as on consoles:
// a cue recorded next follows the palette.
void referToPalette(EditTarget& t, const PaletteDef& p, const std::map<int, CueValues>& recorded) {
  for (const auto& [id, v] : recorded) applyPalette(t.show, t.programmer.values[id], id, p);
}

class RecordPalette final : public GroupsAndPalettesEdit {
 public:
  RecordPalette(std::string name, std::optional<PaletteKind> kind) : name_(std::move(name)), kind_(kind) {}
  std::string label() const override { return "Record palette " + name_; }

 protected:
  Status change(EditTarget& t) override {
    if (name_.empty()) return userError("palette", "a palette needs a name");
    if (auto at = paletteIndexNamed(t.show, name_))
      return userError("palette " + name_, "palette " + inQuotes(t.show.palettes[*at].name) +
                                               " exists; 'update palette " + name_ + "' changes it");
    const PaletteKind kind = kind_ ? *kind_ : paletteKindOfProgrammer(t.show, t.programmer);
    PaletteDef p;
    p.name = name_;
    p.kind = kind;
    p.fixtures = programmerValues(t, kind);
    if (p.fixtures.empty()) return nothingOfKind(kind, name_, t.programmer);
    t.show.palettes.push_back(p);
    referToPalette(t, t.show.palettes.back(), p.fixtures);
    return Ok{};
  }

 private:
  std::string name_;
  std::optional<PaletteKind> kind_;
};

class UpdatePalette final : public GroupsAndPalettesEdit {
 public:
  explicit UpdatePalette(std::string name) : name_(std::move(name)) {}
  std::string label() const override { return "Update palette " + name_; }

 protected:
  Status change(EditTarget& t) override {
    const auto at = paletteIndexNamed(t.show, name_);
    if (!at) return userError("palette " + name_, "no palette is named " + inQuotes(name_));
    PaletteDef& p = t.show.palettes[*at];
    const std::map<int, CueValues> values = programmerValues(t, p.kind);
    if (values.empty()) return nothingOfKind(p.kind, p.name, t.programmer);
    for (const auto& [id, v] : values) {
      // Only what differs from what the palette gives now: its group entries stay the rule.
      CueValues add = v;
      if (auto now = paletteValuesFor(t.show, p, id)) dropEqualValues(add, *now);
      if (hasValues(add)) layValues(p.fixtures[id], add);
    }
    referToPalette(t, p, values);
    return Ok{};
  }

 private:
  std::string name_;
};

class DeletePalette final : public GroupsAndPalettesEdit {
 public:
  explicit DeletePalette(std::string name) : name_(std::move(name)) {}
  std::string label() const override { return "Delete palette " + name_; }

 protected:
  Status change(EditTarget& t) override {
    const auto at = paletteIndexNamed(t.show, name_);
    if (!at) return userError("palette " + name_, "no palette is named " + inQuotes(name_));
    const std::string name = t.show.palettes[*at].name;
    const std::vector<std::string> uses = paletteUses(t.show, name);
    if (!uses.empty())
      return userError("palette " + name, "the palette is used by " + joined(uses) +
                                              "; expected a palette no cue refers to (nothing was deleted)");
    for (const auto& [id, v] : t.programmer.values)
      if (v.palettes.all == name || v.palettes.position == name || v.palettes.color == name || v.palettes.beam == name)
        return userError("palette " + name, "the programmer refers to the palette (fixture " + std::to_string(id) +
                                                "); clear it first (nothing was deleted)");
    t.show.palettes.erase(t.show.palettes.begin() + static_cast<long>(*at));
    return Ok{};
  }

 private:
  std::string name_;
};

class RecordGroup final : public GroupsAndPalettesEdit {
 public:
  RecordGroup(std::string name, std::vector<int> ids) : name_(std::move(name)), ids_(std::move(ids)) {}
  std::string label() const override { return "Record group " + name_; }

 protected:
  Status change(EditTarget& t) override {
    if (name_.empty()) return userError("group", "a group needs a name");
    if (auto at = groupIndexNamed(t.show, name_))
      return userError("group " + name_, "group " + inQuotes(t.show.groups[*at].name) +
                                             " exists; 'delete group " + name_ + "' first to record it again");
    if (ids_.empty())
      return userError("group " + name_, "no fixture is selected; a group is recorded from the selection (\"1 thru 6\" first)");
    for (size_t k = 0; k < ids_.size(); ++k) {
      if (!t.show.findFixture(ids_[k])) return userError("group " + name_, "no fixture has id " + std::to_string(ids_[k]));
      for (size_t j = 0; j < k; ++j)
        if (ids_[j] == ids_[k]) return userError("group " + name_, "fixture " + std::to_string(ids_[k]) + " is named twice");
    }
    t.show.groups.push_back(GroupDef{name_, ids_});
    return Ok{};
  }

 private:
  std::string name_;
  std::vector<int> ids_;
};

class DeleteGroup final : public GroupsAndPalettesEdit {
 public:
  explicit DeleteGroup(std::string name) : name_(std::move(name)) {}
  std::string label() const override { return "Delete group " + name_; }

 protected:
  Status change(EditTarget& t) override {
    const auto at = groupIndexNamed(t.show, name_);
    if (!at) return userError("group " + name_, "no group is named " + inQuotes(name_));
    const std::string name = t.show.groups[*at].name;
    const std::vector<std::string> uses = groupUses(t.show, name);
    if (!uses.empty())
      return userError("group " + name, "the group is used by " + joined(uses) +
                                            "; expected a group nothing refers to (nothing was deleted)");
    t.show.groups.erase(t.show.groups.begin() + static_cast<long>(*at));
    return Ok{};
  }

 private:
  std::string name_;
};

}  // namespace

std::unique_ptr<EditCommand> recordPalette(std::string name, std::optional<PaletteKind> kind) {
  return std::make_unique<RecordPalette>(std::move(name), kind);
}
std::unique_ptr<EditCommand> updatePalette(std::string name) { return std::make_unique<UpdatePalette>(std::move(name)); }
std::unique_ptr<EditCommand> deletePalette(std::string name) { return std::make_unique<DeletePalette>(std::move(name)); }
std::unique_ptr<EditCommand> recordGroup(std::string name, std::vector<int> fixtures) {
  return std::make_unique<RecordGroup>(std::move(name), std::move(fixtures));
}
std::unique_ptr<EditCommand> deleteGroup(std::string name) { return std::make_unique<DeleteGroup>(std::move(name)); }

}  // namespace haze
