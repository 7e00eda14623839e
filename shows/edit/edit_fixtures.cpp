// Fixture commands: place, delete, move, rotate, rename, patch. Each keeps exactly the pieces it
// replaces (a fixture with its index, old values in cues) so that undo puts them back in place and
// a saved show after undo is byte-identical to the one before.
#include <algorithm>
#include <cassert>
#include <cmath>

#include "shows/edit/edit_commands.h"
#include "shows/edit/edit_util.h"

namespace haze {

using edit::fixtureIndex;
using edit::fixturePlace;
using edit::userError;

int nextFixtureId(const Show& show) {
  int maxId = 0;
  for (const FixtureDef& f : show.fixtures) maxId = std::max(maxId, f.id);
  return maxId + 1;
}

Result<int> modeFootprint(const ProfileSet& profiles, const std::string& profile, const std::string& mode) {
  auto it = profiles.find(profile);
  if (it == profiles.end() || !it->second)
    return userError("", "no loaded profile \"" + profile + "\"; expected one of the show's profiles");
  const DmxMode* m = it->second->findMode(mode);
  if (!m) return userError("", "profile \"" + profile + "\" has no mode \"" + mode + "\"");
  return m->footprint();
}

namespace {

constexpr int kUniverseSlots = 512;
constexpr int kMaxUniverse = 63999;  // sACN's largest universe number

// [first, last] slots every other patched fixture of `universe` occupies; footprints of unknown
// profiles count as 1 slot (the show validator reports those).
std::vector<std::pair<int, int>> occupied(const Show& show, const ProfileSet& profiles, int universe, int ignoreId) {
  std::vector<std::pair<int, int>> spans;
  for (const FixtureDef& f : show.fixtures) {
    if (f.id == ignoreId || !f.patch || f.patch->universe != universe) continue;
    Result<int> fp = modeFootprint(profiles, f.profile, f.mode);
    int n = fp ? std::max(1, *fp) : 1;
    spans.emplace_back(f.patch->address, f.patch->address + n - 1);
  }
  std::sort(spans.begin(), spans.end());
  return spans;
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

Result<int> nextFreeAddress(const Show& show, const ProfileSet& profiles, int universe, int footprint, int ignoreId) {
  if (universe < 1 || universe > kMaxUniverse)
    return userError("", "universe " + std::to_string(universe) + " is out of range; expected 1.." + std::to_string(kMaxUniverse));
  int need = std::max(footprint, 1);
  int candidate = 1;
  for (const auto& [first, last] : occupied(show, profiles, universe, ignoreId)) {
    if (candidate + need - 1 < first) break;
    candidate = std::max(candidate, last + 1);
  }
  if (candidate + need - 1 > kUniverseSlots)
    return userError("universe " + std::to_string(universe),
                     "no " + std::to_string(need) + " free DMX slots left in universe " + std::to_string(universe) +
                         "; expected a gap of the mode's footprint");
  return candidate;
}

namespace {

class AddProfile final : public EditCommand {
 public:
  AddProfile(std::string key, ProfileRef ref) : key_(std::move(key)), ref_(std::move(ref)) {}
  std::string label() const override { return "Add profile " + key_; }
  Status apply(EditTarget& t) override {
    if (key_.empty()) return userError("library", "a profile needs a key");
    if (t.show.profiles.count(key_)) return userError("library", "the show already has a profile \"" + key_ + "\"");
    t.show.profiles[key_] = ref_;
    return Ok{};
  }
  // Only right after apply or redo, so no fixture placed later uses it any more.
  void undo(EditTarget& t) override { t.show.profiles.erase(key_); }

 private:
  std::string key_;
  ProfileRef ref_;
};

class PlaceFixture final : public EditCommand {
 public:
  explicit PlaceFixture(FixturePlacement p) : p_(std::move(p)) {}
  std::string label() const override { return "Place fixture " + std::to_string(id_); }
  Status apply(EditTarget& t) override {
    auto prof = t.profiles.find(p_.profile);
    if (prof == t.profiles.end() || !prof->second || !t.show.profiles.count(p_.profile))
      return userError("", "cannot place a fixture of profile \"" + p_.profile + "\"; expected a profile the show has loaded");
    const Profile& profile = *prof->second;
    if (profile.modes.empty() && p_.mode.empty() && p_.universe)
      return userError("", "profile \"" + p_.profile + "\" has no DMX modes to patch; place it unpatched");
    std::string mode = p_.mode.empty() && !profile.modes.empty() ? profile.modes.front().name : p_.mode;
    const DmxMode* m = profile.findMode(mode);
    if (!mode.empty() && !m) return userError("", "profile \"" + p_.profile + "\" has no mode \"" + mode + "\"");
    if (!finite(p_.positionM) || !finite(p_.rotationDeg))
      return userError("", "a fixture's position and rotation must be finite numbers");
    FixtureDef f;
    f.id = nextFixtureId(t.show);
    f.name = p_.name.empty() ? (profile.name.empty() ? p_.profile : profile.name) + " " + std::to_string(f.id) : p_.name;
    f.profile = p_.profile;
    f.mode = mode;
    f.position = p_.positionM;
    f.rotationDeg = p_.rotationDeg;
    if (p_.universe) {
      Result<int> address = nextFreeAddress(t.show, t.profiles, *p_.universe, m ? m->footprint() : 1);
      if (!address) return address.error();
      f.patch = Patch{*p_.universe, *address};
    }
    id_ = f.id;
    t.show.fixtures.push_back(std::move(f));
    return Ok{};
  }
  void undo(EditTarget& t) override {
    assert(!t.show.fixtures.empty() && t.show.fixtures.back().id == id_ && "PlaceFixture::undo: not the last fixture");
    t.show.fixtures.pop_back();
  }

 private:
  FixturePlacement p_;
  int id_ = 0;
};

class DeleteFixtures final : public EditCommand {
 public:
  explicit DeleteFixtures(std::vector<int> ids) : ids_(std::move(ids)) {}
  std::string label() const override {
    return ids_.size() == 1 ? "Delete fixture " + std::to_string(ids_.front()) : "Delete " + std::to_string(ids_.size()) + " fixtures";
  }
  Status apply(EditTarget& t) override {
    if (ids_.empty()) return userError("", "no fixtures to delete; expected at least one fixture id");
    for (int id : ids_)
      if (!fixtureIndex(t.show, id)) return userError(fixturePlace(id), "no fixture with id " + std::to_string(id));
    auto doomed = [&](int id) { return std::find(ids_.begin(), ids_.end(), id) != ids_.end(); };
    removed_.clear();
    cueValues_.clear();
    programmer_.clear();
    for (size_t i = 0; i < t.show.fixtures.size(); ++i)
      if (doomed(t.show.fixtures[i].id)) removed_.emplace_back(i, t.show.fixtures[i]);
    std::erase_if(t.show.fixtures, [&](const FixtureDef& f) { return doomed(f.id); });
    // Groups and palettes name fixtures too: a deleted one leaves them (undo puts them back).
    groups_ = t.show.groups;
    palettes_ = t.show.palettes;
    for (GroupDef& g : t.show.groups) std::erase_if(g.fixtures, doomed);
    for (PaletteDef& p : t.show.palettes) std::erase_if(p.fixtures, [&](const auto& e) { return doomed(e.first); });
    for (size_t l = 0; l < t.show.cueLists.size(); ++l)
      for (size_t c = 0; c < t.show.cueLists[l].cues.size(); ++c) {
        auto& values = t.show.cueLists[l].cues[c].values;
        for (auto it = values.begin(); it != values.end();) {
          if (doomed(it->first)) {
            cueValues_.push_back({l, c, it->first, it->second});
            it = values.erase(it);
          } else {
            ++it;
          }
        }
      }
    for (auto it = t.programmer.values.begin(); it != t.programmer.values.end();) {
      if (doomed(it->first)) {
        programmer_.emplace(it->first, it->second);
        it = t.programmer.values.erase(it);
      } else {
        ++it;
      }
    }
    return Ok{};
  }
  void undo(EditTarget& t) override {
    for (const auto& [index, f] : removed_) t.show.fixtures.insert(t.show.fixtures.begin() + static_cast<long>(index), f);
    t.show.groups = groups_;
    t.show.palettes = palettes_;
    for (const CueValue& v : cueValues_) t.show.cueLists[v.list].cues[v.cue].values[v.id] = v.values;
    for (const auto& [id, v] : programmer_) t.programmer.values[id] = v;
  }

 private:
  struct CueValue {
    size_t list, cue;
    int id;
    CueValues values;
  };
  std::vector<int> ids_;
  std::vector<std::pair<size_t, FixtureDef>> removed_;  // ascending index: reinserting in order restores places
  std::vector<CueValue> cueValues_;
  std::map<int, CueValues> programmer_;
  std::vector<GroupDef> groups_;
  std::vector<PaletteDef> palettes_;
};

// Move and rotate: one vec3 member of a fixture, before and after.
class SetFixtureVector final : public EditCommand {
 public:
  enum class What { Position, Rotation };
  SetFixtureVector(What what, int id, glm::vec3 value) : what_(what), id_(id), after_(value) {}
  std::string label() const override {
    return (what_ == What::Position ? "Move fixture " : "Rotate fixture ") + std::to_string(id_);
  }
  Status apply(EditTarget& t) override {
    auto i = fixtureIndex(t.show, id_);
    if (!i) return userError(fixturePlace(id_), "no fixture with id " + std::to_string(id_));
    if (!finite(after_)) return userError(fixturePlace(id_), "a fixture's position and rotation must be finite numbers");
    glm::vec3& v = member(t.show.fixtures[*i]);
    before_ = v;
    v = after_;
    return Ok{};
  }
  void undo(EditTarget& t) override {
    auto i = fixtureIndex(t.show, id_);
    assert(i && "SetFixtureVector::undo: fixture gone");
    member(t.show.fixtures[*i]) = before_;
  }
  bool absorb(const EditCommand& next) override {
    auto* n = dynamic_cast<const SetFixtureVector*>(&next);
    if (!n || n->what_ != what_ || n->id_ != id_) return false;
    after_ = n->after_;
    return true;
  }

 private:
  glm::vec3& member(FixtureDef& f) const { return what_ == What::Position ? f.position : f.rotationDeg; }
  What what_;
  int id_;
  glm::vec3 after_;
  glm::vec3 before_{0.0f};
};

class RenameFixture final : public EditCommand {
 public:
  RenameFixture(int id, std::string name) : id_(id), after_(std::move(name)) {}
  std::string label() const override { return "Rename fixture " + std::to_string(id_); }
  Status apply(EditTarget& t) override {
    auto i = fixtureIndex(t.show, id_);
    if (!i) return userError(fixturePlace(id_), "no fixture with id " + std::to_string(id_));
    before_ = std::exchange(t.show.fixtures[*i].name, after_);
    return Ok{};
  }
  void undo(EditTarget& t) override { t.show.fixtures[*fixtureIndex(t.show, id_)].name = before_; }

 private:
  int id_;
  std::string after_, before_;
};

class PatchFixture final : public EditCommand {
 public:
  PatchFixture(int id, std::optional<Patch> patch, std::string mode) : id_(id), patch_(patch), mode_(std::move(mode)) {}
  std::string label() const override { return "Patch fixture " + std::to_string(id_); }
  Status apply(EditTarget& t) override {
    auto i = fixtureIndex(t.show, id_);
    if (!i) return userError(fixturePlace(id_), "no fixture with id " + std::to_string(id_));
    FixtureDef& f = t.show.fixtures[*i];
    std::string mode = mode_.empty() ? f.mode : mode_;
    auto prof = t.profiles.find(f.profile);
    if (prof == t.profiles.end() || !prof->second)
      return userError(fixturePlace(id_), "profile \"" + f.profile + "\" is not loaded; cannot check the mode and footprint");
    const DmxMode* m = prof->second->findMode(mode);
    if (!m && (!mode.empty() || patch_))
      return userError(fixturePlace(id_), "profile \"" + f.profile + "\" has no mode \"" + mode + "\"");
    if (patch_) {
      int last = patch_->address + std::max(1, m->footprint()) - 1;
      if (patch_->universe < 1 || patch_->universe > kMaxUniverse)
        return userError(fixturePlace(id_), "universe " + std::to_string(patch_->universe) + " is out of range; expected 1.." +
                                                std::to_string(kMaxUniverse));
      if (patch_->address < 1 || last > kUniverseSlots)
        return userError(fixturePlace(id_), "address " + std::to_string(patch_->address) + " with a footprint of " +
                                                std::to_string(m->footprint()) + " does not fit; expected 1.." +
                                                std::to_string(kUniverseSlots - std::max(1, m->footprint()) + 1));
      for (const FixtureDef& o : t.show.fixtures) {
        if (o.id == id_ || !o.patch || o.patch->universe != patch_->universe) continue;
        Result<int> fp = modeFootprint(t.profiles, o.profile, o.mode);
        int oLast = o.patch->address + (fp ? std::max(1, *fp) : 1) - 1;
        if (o.patch->address <= last && patch_->address <= oLast)
          return userError(fixturePlace(id_), "universe " + std::to_string(patch_->universe) + " slots " +
                                                  std::to_string(patch_->address) + ".." + std::to_string(last) +
                                                  " overlap fixture " + std::to_string(o.id) + " at " +
                                                  std::to_string(o.patch->address) + ".." + std::to_string(oLast) +
                                                  "; expected free slots");
      }
    }
    beforeMode_ = std::exchange(f.mode, mode);
    beforePatch_ = std::exchange(f.patch, patch_);
    return Ok{};
  }
  void undo(EditTarget& t) override {
    FixtureDef& f = t.show.fixtures[*fixtureIndex(t.show, id_)];
    f.mode = beforeMode_;
    f.patch = beforePatch_;
  }

 private:
  int id_;
  std::optional<Patch> patch_;
  std::string mode_;
  std::string beforeMode_;
  std::optional<Patch> beforePatch_;
};

}  // namespace

std::unique_ptr<EditCommand> addProfile(std::string key, ProfileRef ref) { return std::make_unique<AddProfile>(std::move(key), std::move(ref)); }
std::unique_ptr<EditCommand> placeFixture(FixturePlacement placement) { return std::make_unique<PlaceFixture>(std::move(placement)); }
std::unique_ptr<EditCommand> deleteFixtures(std::vector<int> ids) { return std::make_unique<DeleteFixtures>(std::move(ids)); }
std::unique_ptr<EditCommand> moveFixture(int id, glm::vec3 positionM) {
  return std::make_unique<SetFixtureVector>(SetFixtureVector::What::Position, id, positionM);
}
std::unique_ptr<EditCommand> rotateFixture(int id, glm::vec3 rotationDeg) {
  return std::make_unique<SetFixtureVector>(SetFixtureVector::What::Rotation, id, rotationDeg);
}
std::unique_ptr<EditCommand> renameFixture(int id, std::string name) { return std::make_unique<RenameFixture>(id, std::move(name)); }
std::unique_ptr<EditCommand> patchFixture(int id, std::optional<Patch> patch, std::string mode) {
  return std::make_unique<PatchFixture>(id, patch, std::move(mode));
}

}  // namespace haze
