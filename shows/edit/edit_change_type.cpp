// Change fixture type. The command keeps copies of everything it rewrites (fixtures, profiles,
// cue lists, palettes, programmer), so undo gives back the very same show: a save after undo is
// byte-identical to one before.
#include "shows/edit/edit_change_type.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "fixtures/core/text_file.h"
#include "shows/edit/edit_commands.h"
#include "shows/edit/edit_util.h"
#include "shows/palettes.h"

namespace haze {

using edit::fixtureIndex;
using edit::fixturePlace;
using edit::userError;

namespace {

constexpr int kUniverseSlots = 512;

std::string compact(std::string_view s) {
  std::string out;
  for (char c : s)
    if (std::isalnum(static_cast<unsigned char>(c))) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string rgbText(const glm::vec3& c) { return "[" + fmtNum(c.r) + ", " + fmtNum(c.g) + ", " + fmtNum(c.b) + "]"; }

// A slot of wheel `wheel` by name: the same name, else the same letters and digits ("gobo 5" is
// "Gobo5"); empty when the wheel has none.
std::optional<std::string> slotByName(const Profile& p, size_t wheel, const std::string& name) {
  if (p.findGobo(name, wheel)) return name;
  if (wheel < p.goboWheels.size())
    for (const WheelSlot& s : p.goboWheels[wheel].slots)
      if (compact(s.name) == compact(name)) return s.name;
  return std::nullopt;
}

// The colour the new type can make closest to `c`: itself where it mixes, else the nearest slot
// of its first colour wheel (white counts: an open wheel), else white.
glm::vec3 reachableColour(const Profile& p, const glm::vec3& c, std::string* slotName) {
  if (p.colorMixing != ColorMixing::None) return c;
  glm::vec3 best(1.0f);
  float bestD = glm::dot(c - best, c - best);
  if (slotName) *slotName = "open";
  if (!p.colorWheels.empty())
    for (const WheelSlot& s : p.colorWheels.front().slots) {
      if (!s.color) continue;
      const float d = glm::dot(c - *s.color, c - *s.color);
      if (d < bestD) {
        bestD = d;
        best = *s.color;
        if (slotName) *slotName = s.name;
      }
    }
  return best;
}

}  // namespace

CueValues mapValuesToProfile(const CueValues& in, const Profile& to, const std::string& where, std::vector<std::string>& notes) {
  CueValues v = in;
  auto note = [&](const std::string& s) { notes.push_back(where + ": " + s); };
  auto clampTo = [&](std::optional<float>& x, const Range& r, const char* what) {
    if (!x) return;
    const float lo = std::min(r.min, r.max), hi = std::max(r.min, r.max);
    const float c = std::clamp(*x, lo, hi);
    if (c != *x) note(std::string(what) + " " + fmtNum(*x) + " clamped to " + fmtNum(c) + " (the new range is " + fmtNum(lo) +
                      " to " + fmtNum(hi) + ")");
    x = c;
  };
  clampTo(v.panDeg, to.panDeg, "pan");
  clampTo(v.tiltDeg, to.tiltDeg, "tilt");
  clampTo(v.zoomDeg, to.zoomDeg, "zoom");
  if (v.color) {
    std::string slot;
    const glm::vec3 c = reachableColour(to, *v.color, &slot);
    if (c != *v.color) {
      note("colour " + rgbText(*v.color) + (to.colorWheels.empty() ? " is white: the new type has no colour"
                                                                   : " becomes the wheel's nearest slot \"" + slot + "\" " + rgbText(c)));
      v.color = c;
    }
  }
  auto dropIf = [&](auto& x, bool drop, const std::string& why) {
    if (!x || !drop) return;
    note(why);
    x.reset();
  };
  // Gobos by name on the same wheel; an unknown one opens.
  for (size_t wheel : {size_t{0}, size_t{1}}) {
    auto& gobo = wheel == 0 ? v.gobo : v.gobo2;
    if (!gobo || *gobo == "Open") continue;
    if (auto same = slotByName(to, wheel, *gobo)) {
      gobo = *same;
      continue;
    }
    note("gobo \"" + *gobo + "\" is not on the new type's " + (wheel == 0 ? "first" : "second") + " gobo wheel; Open");
    gobo = "Open";
  }
  if (v.gobo2 && to.goboWheels.size() < 2 && *v.gobo2 == "Open") v.gobo2.reset();
  dropIf(v.goboRotationDeg, to.goboWheels.empty(), "gobo rotation dropped: the new type has no gobo wheel");
  dropIf(v.goboSpinDegS, to.goboWheels.empty(), "gobo spin dropped: the new type has no gobo wheel");
  dropIf(v.gobo2RotationDeg, to.goboWheels.size() < 2, "second gobo rotation dropped: the new type has no second gobo wheel");
  dropIf(v.gobo2SpinDegS, to.goboWheels.size() < 2, "second gobo spin dropped: the new type has no second gobo wheel");
  if (v.color2 && *v.color2 != "Open") {
    bool found = false;
    if (to.colorWheels.size() > 1)
      for (const WheelSlot& s : to.colorWheels[1].slots) found = found || s.name == *v.color2;
    if (!found) {
      note("second colour wheel slot \"" + *v.color2 + "\" is not on the new type; Open");
      v.color2 = "Open";
    }
  }
  if (v.animation && *v.animation != "Open" && !to.findAnimation(*v.animation)) {
    note("animation \"" + *v.animation + "\" is not on the new type; Open");
    v.animation = "Open";
  }
  dropIf(v.animationRotationDeg, to.animationWheels.empty(), "animation rotation dropped: the new type has no animation wheel");
  dropIf(v.animationSpinDegS, to.animationWheels.empty(), "animation spin dropped: the new type has no animation wheel");
  if (v.prism && *v.prism != "Open" && !to.findPrism(*v.prism)) {
    if (!to.prisms.empty()) {
      note("prism \"" + *v.prism + "\" becomes the new type's \"" + to.prisms.front().name + "\"");
      v.prism = to.prisms.front().name;
    } else {
      note("prism \"" + *v.prism + "\" dropped: the new type has no prism");
      v.prism = "Open";
    }
  }
  dropIf(v.prismRotationDeg, to.prisms.empty(), "prism rotation dropped: the new type has no prism");
  dropIf(v.prismSpinDegS, to.prisms.empty(), "prism spin dropped: the new type has no prism");
  if (v.frost && *v.frost > 0.0f && !to.hasFrost) {
    note("frost " + fmtNum(*v.frost) + " dropped: the new type has no frost");
    v.frost.reset();
  }
  dropIf(v.gateFocus, !to.hasGateFocus, "focus dropped: the new type has no focus");
  if (v.blades && !to.hasBlades) {
    const bool in = std::any_of(v.blades->begin(), v.blades->end(), [](const glm::vec2& e) { return e.x > 0.0f || e.y > 0.0f; });
    if (in) note("framing blades dropped: the new type has none");
    v.blades.reset();
  }
  dropIf(v.bladeRotationDeg, !to.hasBlades, "blade rotation dropped: the new type has no framing blades");
  for (auto it = v.cells.begin(); it != v.cells.end();) {
    if (static_cast<size_t>(it->first) < to.cells.size()) {
      ++it;
      continue;
    }
    note("cell " + std::to_string(it->first + 1) + " dropped: the new type has " + std::to_string(to.cells.size()) + " cells");
    it = v.cells.erase(it);
  }
  return v;
}

namespace {

class ChangeType final : public EditCommand {
 public:
  ChangeType(ChangeTypeRequest r, std::shared_ptr<ChangeTypeReport> report) : r_(std::move(r)), report_(std::move(report)) {}
  std::string label() const override {
    return r_.fixtures.size() == 1 ? "Change type of fixture " + std::to_string(r_.fixtures.front())
                                   : "Change type of " + std::to_string(r_.fixtures.size()) + " fixtures";
  }

  Status apply(EditTarget& t) override {
    if (r_.fixtures.empty()) return userError("", "no fixtures to change; expected at least one fixture id");
    if (!r_.profile || r_.profileKey.empty()) return userError("", "no new fixture type given");
    const Profile& to = *r_.profile;
    if (to.modes.empty()) return userError("", "the new type \"" + to.name + "\" has no DMX modes");
    const std::string mode = r_.mode.empty() ? to.modes.front().name : r_.mode;
    const DmxMode* m = to.findMode(mode);
    if (!m) {
      std::string names;
      for (const DmxMode& x : to.modes) names += (names.empty() ? "\"" : ", \"") + x.name + "\"";
      return userError("", "the new type \"" + to.name + "\" has no mode \"" + mode + "\"; its modes are: " + names);
    }
    for (int id : r_.fixtures)
      if (!fixtureIndex(t.show, id)) return userError(fixturePlace(id), "no fixture with id " + std::to_string(id));
    // The new footprints from each fixture's own start, against every other patched fixture and
    // one another.
    auto changing = [&](int id) { return std::find(r_.fixtures.begin(), r_.fixtures.end(), id) != r_.fixtures.end(); };
    struct Span {
      int id, universe, first, last;
    };
    std::vector<Span> spans, others;
    for (const FixtureDef& f : t.show.fixtures) {
      if (!f.patch) continue;
      if (changing(f.id)) {
        spans.push_back({f.id, f.patch->universe, f.patch->address, f.patch->address + m->footprint() - 1});
      } else {
        Result<int> fp = modeFootprint(t.profiles, f.profile, f.mode);
        others.push_back({f.id, f.patch->universe, f.patch->address, f.patch->address + (fp ? std::max(1, *fp) : 1) - 1});
      }
    }
    std::vector<std::string> clashes;
    for (size_t k = 0; k < spans.size(); ++k) {
      const Span& s = spans[k];
      auto where = [](const Span& x) {
        return "fixture " + std::to_string(x.id) + " (universe " + std::to_string(x.universe) + " " + std::to_string(x.first) + "-" +
               std::to_string(x.last) + ")";
      };
      if (s.last > kUniverseSlots) clashes.push_back(where(s) + " runs past channel 512");
      for (const Span& o : others)
        if (o.universe == s.universe && s.first <= o.last && o.first <= s.last) clashes.push_back(where(s) + " overlaps " + where(o));
      for (size_t j = 0; j < k; ++j)
        if (spans[j].universe == s.universe && s.first <= spans[j].last && spans[j].first <= s.last)
          clashes.push_back(where(s) + " overlaps " + where(spans[j]));
    }
    if (!clashes.empty()) {
      std::string list;
      for (size_t k = 0; k < clashes.size() && k < 20; ++k) list += (k ? "; " : "") + clashes[k];
      if (clashes.size() > 20) list += "; and " + std::to_string(clashes.size() - 20) + " more";
      return userError("", "mode \"" + mode + "\" needs " + std::to_string(m->footprint()) + " channels per fixture: " + list +
                               "; repatch first or pick a smaller mode");
    }

    before_ = Snapshot{t.show.fixtures, t.show.profiles, t.show.cueLists, t.show.palettes, t.programmer};
    std::vector<std::string> notes;
    int mapped = 0;
    auto mapEntry = [&](CueValues& v, const std::string& where) {
      v = mapValuesToProfile(v, to, where, notes);
      ++mapped;
    };
    for (size_t li = 0; li < t.show.cueLists.size(); ++li) {
      CueList& l = t.show.cueLists[li];
      const std::string list = t.show.cueLists.size() > 1 ? " of list \"" + l.name + "\"" : "";
      for (Cue& c : l.cues) {
        for (auto& [id, v] : c.values)
          if (changing(id)) mapEntry(v, "cue " + c.number + list + " fixture " + std::to_string(id));
        for (const EffectDef& e : c.effects) {
          const GroupDef* g = t.show.findGroup(e.group);
          if (!g || std::none_of(g->fixtures.begin(), g->fixtures.end(), changing)) continue;
          const bool lacks = (e.attribute == "frost" && !to.hasFrost) || (e.attribute == "gobo_rotation" && to.goboWheels.empty()) ||
                             (e.attribute == "prism_rotation" && to.prisms.empty()) ||
                             ((e.attribute == "pan" || e.attribute == "tilt" || e.attribute == "position") && to.panDeg.max <= to.panDeg.min);
          if (lacks) notes.push_back("cue " + c.number + list + " effect on " + e.attribute + " of group \"" + e.group +
                                     "\": the new type has no " + e.attribute + "; it does nothing on the changed fixtures");
        }
      }
    }
    // Palettes: a group entry whose fixtures all change is mapped where it is; a changing fixture
    // of a group that keeps other types gets an entry of its own with what the palette gave it,
    // mapped (an entry of its own is laid over the group's).
    for (PaletteDef& p : t.show.palettes) {
      const PaletteDef original = p;
      std::vector<const GroupDef*> mixed;
      for (auto& [group, v] : p.groups) {
        const GroupDef* g = t.show.findGroup(group);
        if (!g || std::none_of(g->fixtures.begin(), g->fixtures.end(), changing)) continue;
        if (std::all_of(g->fixtures.begin(), g->fixtures.end(), changing))
          mapEntry(v, "palette \"" + p.name + "\" group \"" + group + "\"");
        else
          mixed.push_back(g);
      }
      for (int id : r_.fixtures) {
        const bool inMixed = std::any_of(mixed.begin(), mixed.end(), [&](const GroupDef* g) {
          return std::find(g->fixtures.begin(), g->fixtures.end(), id) != g->fixtures.end();
        });
        const std::string where = "palette \"" + p.name + "\" fixture " + std::to_string(id);
        if (inMixed) {
          if (auto given = paletteValuesFor(t.show, original, id)) {
            p.fixtures[id] = *given;
            mapEntry(p.fixtures[id], where);
          }
        } else if (auto it = p.fixtures.find(id); it != p.fixtures.end()) {
          mapEntry(it->second, where);
        }
      }
    }
    for (auto& [id, v] : t.programmer.values)
      if (changing(id)) mapEntry(v, "programmer fixture " + std::to_string(id));
    if (!t.show.profiles.count(r_.profileKey)) t.show.profiles[r_.profileKey] = r_.ref;
    for (FixtureDef& f : t.show.fixtures)
      if (changing(f.id)) {
        f.profile = r_.profileKey;
        f.mode = mode;
      }
    if (report_) {
      report_->lines = std::move(notes);
      report_->valuesMapped = mapped;
    }
    return Ok{};
  }

  void undo(EditTarget& t) override {
    t.show.fixtures = before_.fixtures;
    t.show.profiles = before_.profiles;
    t.show.cueLists = before_.cueLists;
    t.show.palettes = before_.palettes;
    t.programmer = before_.programmer;
  }

 private:
  struct Snapshot {
    std::vector<FixtureDef> fixtures;
    std::map<std::string, ProfileRef> profiles;
    std::vector<CueList> cueLists;
    std::vector<PaletteDef> palettes;
    Programmer programmer;
  };
  ChangeTypeRequest r_;
  std::shared_ptr<ChangeTypeReport> report_;
  Snapshot before_;
};

}  // namespace

std::unique_ptr<EditCommand> changeFixtureType(ChangeTypeRequest request, std::shared_ptr<ChangeTypeReport> report) {
  return std::make_unique<ChangeType>(std::move(request), std::move(report));
}

}  // namespace haze
