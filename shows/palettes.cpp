// Groups and palettes (see palettes.h): resolution is a plain overlay of optional values, done
// every time a cue plays, so nothing copies a palette's values into the cues that use it.
#include "shows/palettes.h"

#include <cctype>
#include <map>
#include <set>

#include "shows/show_json.h"

namespace haze {

const char* paletteKindName(PaletteKind kind) {
  switch (kind) {
    case PaletteKind::Position: return "position";
    case PaletteKind::Color: return "color";
    case PaletteKind::Beam: return "beam";
    case PaletteKind::All: break;
  }
  return "all";
}

std::optional<PaletteKind> paletteKindFromName(const std::string& name) {
  for (PaletteKind k : {PaletteKind::Position, PaletteKind::Color, PaletteKind::Beam, PaletteKind::All})
    if (name == paletteKindName(k)) return k;
  return std::nullopt;
}

void layValues(CueValues& u, const CueValues& o) {
  auto lay = [](auto& dst, const auto& src) {
    if (src) dst = src;
  };
  lay(u.intensity, o.intensity);
  lay(u.panDeg, o.panDeg);
  lay(u.tiltDeg, o.tiltDeg);
  lay(u.zoomDeg, o.zoomDeg);
  lay(u.goboRotationDeg, o.goboRotationDeg);
  lay(u.iris, o.iris);
  lay(u.color, o.color);
  lay(u.gobo, o.gobo);
  lay(u.gobo2, o.gobo2);
  lay(u.color2, o.color2);
  lay(u.ctoMired, o.ctoMired);
  lay(u.gobo2RotationDeg, o.gobo2RotationDeg);
  lay(u.goboSpinDegS, o.goboSpinDegS);
  lay(u.gobo2SpinDegS, o.gobo2SpinDegS);
  lay(u.prismSpinDegS, o.prismSpinDegS);
  lay(u.animation, o.animation);
  lay(u.animationRotationDeg, o.animationRotationDeg);
  lay(u.animationSpinDegS, o.animationSpinDegS);
  for (const auto& [k, c] : o.cells) {
    lay(u.cells[k].intensity, c.intensity);
    lay(u.cells[k].color, c.color);
  }
  lay(u.frost, o.frost);
  lay(u.gateFocus, o.gateFocus);
  lay(u.prismRotationDeg, o.prismRotationDeg);
  lay(u.bladeRotationDeg, o.bladeRotationDeg);
  lay(u.prism, o.prism);
  lay(u.blades, o.blades);
  lay(u.shutter, o.shutter);
}

std::optional<CueValues> paletteValuesFor(const Show& show, const PaletteDef& palette, int fixtureId) {
  std::optional<CueValues> out;
  for (const GroupDef& g : show.groups) {
    auto entry = palette.groups.find(g.name);
    if (entry == palette.groups.end()) continue;
    bool member = false;
    for (int id : g.fixtures) member = member || id == fixtureId;
    if (!member) continue;
    if (!out) out = CueValues{};
    layValues(*out, entry->second);
  }
  if (auto f = palette.fixtures.find(fixtureId); f != palette.fixtures.end()) {
    if (!out) out = CueValues{};
    layValues(*out, f->second);
  }
  return out;
}

CueValues resolveValues(const Show& show, int fixtureId, const CueValues& values) {
  if (values.palettes.empty()) return values;
  CueValues out;
  for (const std::string* name : {&values.palettes.all, &values.palettes.position, &values.palettes.color,
                                  &values.palettes.beam}) {
    if (name->empty()) continue;
    if (const PaletteDef* p = show.findPalette(*name))
      if (auto v = paletteValuesFor(show, *p, fixtureId)) layValues(out, *v);
  }
  layValues(out, values);
  out.palettes = values.palettes;
  return out;
}

namespace {

// Calls f(member) for every optional value of CueValues (cells aside).
template <typename F>
void forEachValue(F f) {
  f(&CueValues::intensity);
  f(&CueValues::panDeg);
  f(&CueValues::tiltDeg);
  f(&CueValues::zoomDeg);
  f(&CueValues::goboRotationDeg);
  f(&CueValues::iris);
  f(&CueValues::color);
  f(&CueValues::gobo);
  f(&CueValues::gobo2);
  f(&CueValues::color2);
  f(&CueValues::ctoMired);
  f(&CueValues::gobo2RotationDeg);
  f(&CueValues::goboSpinDegS);
  f(&CueValues::gobo2SpinDegS);
  f(&CueValues::prismSpinDegS);
  f(&CueValues::animation);
  f(&CueValues::animationRotationDeg);
  f(&CueValues::animationSpinDegS);
  f(&CueValues::frost);
  f(&CueValues::gateFocus);
  f(&CueValues::prismRotationDeg);
  f(&CueValues::bladeRotationDeg);
  f(&CueValues::prism);
  f(&CueValues::blades);
  f(&CueValues::shutter);
}

std::string lowered(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::string& paletteSlot(PaletteRefs& r, PaletteKind kind) {
  switch (kind) {
    case PaletteKind::Position: return r.position;
    case PaletteKind::Color: return r.color;
    case PaletteKind::Beam: return r.beam;
    case PaletteKind::All: break;
  }
  return r.all;
}

const std::string& paletteSlot(const PaletteRefs& r, PaletteKind kind) {
  return paletteSlot(const_cast<PaletteRefs&>(r), kind);
}

CueValues valuesOfKind(PaletteKind kind, const CueValues& v) {
  CueValues out;
  switch (kind) {
    case PaletteKind::Position:
      out.panDeg = v.panDeg;
      out.tiltDeg = v.tiltDeg;
      return out;
    case PaletteKind::Color:
      out.color = v.color;
      for (const auto& [k, c] : v.cells)
        if (c.color) out.cells[k].color = c.color;
      return out;
    case PaletteKind::Beam:
      out = v;
      out.palettes = {};
      out.intensity.reset();
      out.panDeg.reset();
      out.tiltDeg.reset();
      out.color.reset();
      out.cells.clear();
      return out;
    case PaletteKind::All: break;
  }
  out = v;
  out.palettes = {};
  return out;
}

void clearValues(CueValues& v, const CueValues& mask) {
  forEachValue([&](auto m) {
    if (mask.*m) (v.*m).reset();
  });
  for (const auto& [k, c] : mask.cells) {
    auto it = v.cells.find(k);
    if (it == v.cells.end()) continue;
    if (c.intensity) it->second.intensity.reset();
    if (c.color) it->second.color.reset();
    if (!it->second.intensity && !it->second.color) v.cells.erase(it);
  }
}

void dropEqualValues(CueValues& v, const CueValues& ref) {
  forEachValue([&](auto m) {
    if (v.*m && ref.*m && *(v.*m) == *(ref.*m)) (v.*m).reset();
  });
  for (auto it = v.cells.begin(); it != v.cells.end();) {
    auto r = ref.cells.find(it->first);
    if (r != ref.cells.end()) {
      if (it->second.intensity && it->second.intensity == r->second.intensity) it->second.intensity.reset();
      if (it->second.color && it->second.color == r->second.color) it->second.color.reset();
    }
    it = !it->second.intensity && !it->second.color ? v.cells.erase(it) : std::next(it);
  }
}

bool hasValues(const CueValues& v) {
  CueValues bare = v;
  bare.palettes = {};
  return !(bare == CueValues{});
}

namespace {
bool overlapping(const CueValues& a, const CueValues& b) {
  bool any = false;
  forEachValue([&](auto m) { any = any || (a.*m && b.*m); });
  for (const auto& [k, c] : a.cells)
    if (auto it = b.cells.find(k); it != b.cells.end())
      any = any || (c.intensity && it->second.intensity) || (c.color && it->second.color);
  return any;
}
}  // namespace

bool applyPalette(const Show& show, CueValues& entry, int fixtureId, const PaletteDef& palette) {
  const auto given = paletteValuesFor(show, palette, fixtureId);
  if (!given) return false;
  clearValues(entry, *given);
  if (palette.kind == PaletteKind::All)
    for (PaletteKind k : {PaletteKind::Position, PaletteKind::Color, PaletteKind::Beam}) {
      std::string& slot = paletteSlot(entry.palettes, k);
      const PaletteDef* other = slot.empty() ? nullptr : show.findPalette(slot);
      const auto its = other ? paletteValuesFor(show, *other, fixtureId) : std::nullopt;
      if (its && overlapping(*its, *given)) slot.clear();
    }
  paletteSlot(entry.palettes, palette.kind) = palette.name;
  return true;
}

std::optional<size_t> paletteIndexNamed(const Show& show, const std::string& name) {
  for (size_t i = 0; i < show.palettes.size(); ++i)
    if (lowered(show.palettes[i].name) == lowered(name)) return i;
  return std::nullopt;
}

std::optional<size_t> groupIndexNamed(const Show& show, const std::string& name) {
  for (size_t i = 0; i < show.groups.size(); ++i)
    if (lowered(show.groups[i].name) == lowered(name)) return i;
  return std::nullopt;
}

std::vector<std::string> paletteUses(const Show& show, const std::string& name) {
  std::vector<std::string> uses;
  for (const CueList& l : show.cueLists)
    for (const Cue& q : l.cues) {
      bool used = false;
      for (const auto& [id, v] : q.values)
        used = used || v.palettes.all == name || v.palettes.position == name || v.palettes.color == name ||
               v.palettes.beam == name;
      if (used) uses.push_back("cue " + q.number + " of \"" + l.name + "\"");
    }
  return uses;
}

std::vector<std::string> groupUses(const Show& show, const std::string& name) {
  std::vector<std::string> uses;
  for (const PaletteDef& p : show.palettes)
    if (p.groups.count(name)) uses.push_back("palette \"" + p.name + "\"");
  for (const CueList& l : show.cueLists)
    for (const Cue& q : l.cues) {
      bool used = q.timing.fan && q.timing.fan->group == name;
      for (const EffectDef& e : q.effects) used = used || e.group == name;
      if (used) uses.push_back("cue " + q.number + " of \"" + l.name + "\"");
    }
  return uses;
}

std::string attributeOutsideKind(PaletteKind kind, const CueValues& v) {
  if (kind == PaletteKind::All) return "";
  const bool position = kind == PaletteKind::Position, color = kind == PaletteKind::Color,
             beam = kind == PaletteKind::Beam;
  if (v.intensity) return "intensity";
  if (!position && v.panDeg) return "pan";
  if (!position && v.tiltDeg) return "tilt";
  if (!color && v.color) return "color";
  if (!color && v.color2) return "color2";
  if (!color && v.ctoMired) return "cto";
  for (const auto& [k, c] : v.cells) {
    if (c.intensity) return "cells/" + std::to_string(k + 1) + "/intensity";
    if (!color && c.color) return "cells/" + std::to_string(k + 1) + "/color";
  }
  if (!beam) {
    if (v.zoomDeg) return "zoom";
    if (v.gobo) return "gobo";
    if (v.goboRotationDeg) return "gobo_rotation";
    if (v.gobo2) return "gobo2";
    if (v.gobo2RotationDeg) return "gobo2_rotation";
    if (v.goboSpinDegS) return "gobo_spin";
    if (v.gobo2SpinDegS) return "gobo2_spin";
    if (v.prismSpinDegS) return "prism_spin";
    if (v.animation) return "animation";
    if (v.animationRotationDeg) return "animation_rotation";
    if (v.animationSpinDegS) return "animation_spin";
    if (v.iris) return "iris";
    if (v.frost) return "frost";
    if (v.gateFocus) return "focus";
    if (v.prism) return "prism";
    if (v.prismRotationDeg) return "prism_rotation";
    if (v.blades) return "blades";
    if (v.bladeRotationDeg) return "blade_rotation";
    if (v.shutter) return "shutter";
  }
  return "";
}

namespace {

std::string quotedList(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "\"" : ", \"") + n + "\"";
  return out.empty() ? "(none)" : out;
}

struct Checker {
  const Show& show;
  std::vector<Error> problems;

  void problem(std::string ptr, std::string message) {
    problems.push_back(Error{show.file.string(), std::move(ptr), std::move(message)});
  }

  void groups() {
    std::map<std::string, size_t> names;
    for (size_t i = 0; i < show.groups.size(); ++i) {
      const GroupDef& g = show.groups[i];
      const std::string p = "/groups/" + std::to_string(i);
      if (!g.name.empty()) {
        auto [it, fresh] = names.emplace(g.name, i);
        if (!fresh)
          problem(p + "/name", "group name \"" + g.name + "\" is already used by /groups/" + std::to_string(it->second) +
                                   "; expected unique names");
      }
      std::set<int> seen;
      for (size_t k = 0; k < g.fixtures.size(); ++k) {
        const int id = g.fixtures[k];
        const std::string fp = p + "/fixtures/" + std::to_string(k);
        if (!show.findFixture(id))
          problem(fp, "group \"" + g.name + "\" names fixture " + std::to_string(id) +
                          ", which is not in /fixtures; expected the id of a fixture of the show");
        else if (!seen.insert(id).second)
          problem(fp, "group \"" + g.name + "\" names fixture " + std::to_string(id) +
                          " twice; expected each fixture once (the order is the group's order)");
      }
    }
  }

  void palettes() {
    std::map<std::string, size_t> names;
    std::vector<std::string> groupNames;
    for (const GroupDef& g : show.groups) groupNames.push_back(g.name);
    for (size_t i = 0; i < show.palettes.size(); ++i) {
      const PaletteDef& pal = show.palettes[i];
      const std::string p = "/palettes/" + std::to_string(i);
      if (!pal.name.empty()) {
        auto [it, fresh] = names.emplace(pal.name, i);
        if (!fresh)
          problem(p + "/name", "palette name \"" + pal.name + "\" is already used by /palettes/" +
                                   std::to_string(it->second) + "; expected unique names");
      }
      auto kindCheck = [&](const std::string& vp, const CueValues& v) {
        const std::string bad = attributeOutsideKind(pal.kind, v);
        if (!bad.empty())
          problem(vp + "/" + bad, std::string("a ") + paletteKindName(pal.kind) + " palette cannot hold " + bad +
                                      "; expected " + kindAttributes(pal.kind) + " (or make it an \"all\" palette)");
      };
      for (const auto& [name, v] : pal.groups) {
        const std::string gp = p + "/groups/" + pointerToken(name);
        if (!show.findGroup(name))
          problem(gp, "palette \"" + pal.name + "\" has values for group \"" + name +
                          "\", which is not in /groups; expected one of: " + quotedList(groupNames));
        kindCheck(gp, v);
      }
      for (const auto& [id, v] : pal.fixtures) {
        const std::string fp = p + "/fixtures/" + std::to_string(id);
        if (!show.findFixture(id))
          problem(fp, "palette \"" + pal.name + "\" has values for fixture " + std::to_string(id) +
                          ", which is not in /fixtures; expected the id of a fixture of the show");
        kindCheck(fp, v);
      }
    }
  }

  static std::string kindAttributes(PaletteKind kind) {
    switch (kind) {
      case PaletteKind::Position: return "pan and tilt only";
      case PaletteKind::Color: return "color and cell colours only";
      case PaletteKind::Beam:
        return "beam attributes only (zoom, gobo, gobo_rotation, gobo2, gobo2_rotation, the spins, animation, animation_rotation, iris, "
               "frost, focus, prism, prism_rotation, blades, blade_rotation, shutter)";
      case PaletteKind::All: break;
    }
    return "any attribute";
  }

  void references() {
    std::vector<std::string> paletteNames;
    for (const PaletteDef& p : show.palettes) paletteNames.push_back(p.name);
    for (size_t li = 0; li < show.cueLists.size(); ++li)
      for (size_t ci = 0; ci < show.cueLists[li].cues.size(); ++ci) {
        const Cue& cue = show.cueLists[li].cues[ci];
        if (cue.timing.fan && !cue.timing.fan->group.empty() && !show.findGroup(cue.timing.fan->group)) {
          std::vector<std::string> groupNames;
          for (const GroupDef& g : show.groups) groupNames.push_back(g.name);
          problem("/cue_lists/" + std::to_string(li) + "/cues/" + std::to_string(ci) + "/timing/fan/group",
                  "the fan names group \"" + cue.timing.fan->group + "\", which is not in /groups; expected one of: " +
                      quotedList(groupNames));
        }
        for (size_t ei = 0; ei < cue.effects.size(); ++ei)
          if (!cue.effects[ei].group.empty() && !show.findGroup(cue.effects[ei].group)) {
            std::vector<std::string> groupNames;
            for (const GroupDef& g : show.groups) groupNames.push_back(g.name);
            problem("/cue_lists/" + std::to_string(li) + "/cues/" + std::to_string(ci) + "/effects/" +
                        std::to_string(ei) + "/group",
                    "the effect names group \"" + cue.effects[ei].group + "\", which is not in /groups; expected one of: " +
                        quotedList(groupNames));
          }
        for (const auto& [id, v] : cue.values) {
          const std::string vp = "/cue_lists/" + std::to_string(li) + "/cues/" + std::to_string(ci) + "/values/" +
                                 std::to_string(id) + "/palettes/";
          const std::pair<PaletteKind, const std::string*> slots[] = {{PaletteKind::All, &v.palettes.all},
                                                                        {PaletteKind::Position, &v.palettes.position},
                                                                        {PaletteKind::Color, &v.palettes.color},
                                                                        {PaletteKind::Beam, &v.palettes.beam}};
          for (const auto& [kind, name] : slots) {
            if (name->empty()) continue;
            const std::string rp = vp + paletteKindName(kind);
            const PaletteDef* pal = show.findPalette(*name);
            if (!pal) {
              problem(rp, "no palette \"" + *name + "\"; expected one of: " + quotedList(paletteNames));
            } else if (pal->kind != kind) {
              problem(rp, "palette \"" + *name + "\" is a " + paletteKindName(pal->kind) + " palette; expected a " +
                              paletteKindName(kind) + " palette here");
            } else if (show.findFixture(id) && !paletteValuesFor(show, *pal, id)) {
              problem(rp, "palette \"" + *name + "\" has no value for fixture " + std::to_string(id) +
                              "; expected a palette with an entry for the fixture or for a group holding it");
            }
          }
        }
      }
  }
};

}  // namespace

std::vector<Error> checkGroupsAndPalettes(const Show& show) {
  Checker c{show, {}};
  c.groups();
  c.palettes();
  c.references();
  return std::move(c.problems);
}

}  // namespace haze
