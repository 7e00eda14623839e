// Cross-checks of a parsed show against its profiles and itself (see show_validate.h). Each
// problem names the JSON pointer of the value to fix and, where two values clash, the other one.
#include "shows/show_validate.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <utility>

#include <glm/geometric.hpp>

#include "shows/cue_number.h"
#include "shows/palettes.h"
#include "shows/timecode.h"
#include "shows/show_json.h"

namespace haze {

namespace {

std::string num(float v) {
  std::ostringstream s;
  s << tidy(v);
  return s.str();
}

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "(none)" : out;
}

struct Checker {
  const Show& show;
  const ProfileSet& profiles;
  std::vector<Error> problems;

  void problem(std::string ptr, std::string message) {
    problems.push_back(Error{show.file.string(), std::move(ptr), std::move(message)});
  }

  const Profile* profileOf(const FixtureDef& f) const {
    auto it = profiles.find(f.profile);
    return it == profiles.end() ? nullptr : it->second.get();
  }

  void venue() {
    if (show.venueGltf.empty()) return;
    std::error_code ec;
    std::filesystem::path p = show.resolve(show.venueGltf);
    if (!std::filesystem::is_regular_file(p, ec))
      problem("/venue/gltf", "venue file \"" + show.venueGltf + "\" not found (looked for " +
                                 std::filesystem::absolute(p, ec).lexically_normal().string() + ")");
  }

  void cameras() {
    std::map<std::string, size_t> seen;
    for (size_t i = 0; i < show.cameras.size(); ++i) {
      const CameraDef& c = show.cameras[i];
      const std::string p = "/cameras/" + std::to_string(i);
      if (!c.name.empty()) {
        auto [it, fresh] = seen.emplace(c.name, i);
        if (!fresh)
          problem(p + "/name", "camera name \"" + c.name + "\" is already used by /cameras/" +
                                   std::to_string(it->second) + "; expected unique names");
      }
      glm::vec3 view = c.target - c.position;
      if (glm::length(view) < 1e-6f) {
        problem(p + "/target", "the camera's target is its own position; expected a point it looks at");
      } else if (glm::length(c.up) < 1e-6f) {
        problem(p + "/up", "the up vector is zero; expected a direction such as [0, 1, 0]");
      } else if (glm::length(glm::cross(glm::normalize(view), glm::normalize(c.up))) < 1e-4f) {
        problem(p + "/up", "the up vector is parallel to the viewing direction; expected one across it");
      }
      // Ten stops either way of the meter is already a white sheet or a black frame.
      if (c.exposure && !c.exposure->manual && std::abs(c.exposure->ev) > 10.0f)
        problem(p + "/exposure/ev", "an auto exposure offset of " + std::to_string(c.exposure->ev) +
                                        " EV renders white or black; expected -10..10");
    }
  }

  struct Span {
    int universe, first, last;
    size_t index;
  };

  void fixtures() {
    std::map<int, size_t> ids;
    std::vector<Span> spans;
    std::vector<std::string> profileNames;
    for (const auto& [name, ref] : show.profiles) profileNames.push_back(name);
    for (size_t i = 0; i < show.fixtures.size(); ++i) {
      const FixtureDef& f = show.fixtures[i];
      const std::string p = "/fixtures/" + std::to_string(i);
      if (f.id > 0) {
        auto [it, fresh] = ids.emplace(f.id, i);
        if (!fresh)
          problem(p + "/id", "fixture id " + std::to_string(f.id) + " is already used by /fixtures/" +
                                 std::to_string(it->second) + "; expected unique ids");
      }
      if (f.profile.empty()) continue;
      if (!show.profiles.count(f.profile)) {
        problem(p + "/profile", "unknown profile \"" + f.profile + "\"; expected one of the show's profiles: " +
                                    joinNames(profileNames));
        continue;
      }
      const Profile* prof = profileOf(f);
      if (!prof) continue;  // failed to load: reported at /profiles/NAME
      const DmxMode* mode = nullptr;
      if (!f.mode.empty()) {
        mode = prof->findMode(f.mode);
        if (!mode) {
          std::vector<std::string> modes;
          for (const DmxMode& m : prof->modes) modes.push_back("\"" + m.name + "\"");
          problem(p + "/mode", "profile \"" + f.profile + "\" has no DMX mode \"" + f.mode + "\"; its modes are: " +
                                   joinNames(modes));
          continue;
        }
      } else if (!prof->modes.empty()) {
        mode = &prof->modes.front();  // no mode named: the profile's first
      }
      if (!f.patch) continue;
      if (!mode) {
        problem(p + "/patch", "profile \"" + f.profile + "\" has no DMX modes, so the fixture cannot be patched; "
                              "expected no patch");
        continue;
      }
      int footprint = std::max(1, mode->footprint());
      int last = f.patch->address + footprint - 1;
      if (last > 512) {
        problem(p + "/patch/address", "mode \"" + mode->name + "\" needs " + std::to_string(footprint) +
                                          " channels, so address " + std::to_string(f.patch->address) +
                                          " would run to channel " + std::to_string(last) +
                                          ", past 512; expected an address of at most " +
                                          std::to_string(513 - footprint));
        continue;
      }
      spans.push_back(Span{f.patch->universe, f.patch->address, last, i});
    }
    // Overlaps: sweep each universe in address order, keeping the span that reaches furthest.
    std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) {
      return std::tie(a.universe, a.first, a.index) < std::tie(b.universe, b.first, b.index);
    });
    const Span* reach = nullptr;
    for (const Span& s : spans) {
      if (reach && reach->universe == s.universe && s.first <= reach->last) {
        const Span& later = s.index > reach->index ? s : *reach;
        const Span& earlier = s.index > reach->index ? *reach : s;
        const FixtureDef& e = show.fixtures[earlier.index];
        problem("/fixtures/" + std::to_string(later.index) + "/patch/address",
                "channels " + std::to_string(later.first) + "-" + std::to_string(later.last) + " of universe " +
                    std::to_string(s.universe) + " overlap fixture " + std::to_string(e.id) + " (/fixtures/" +
                    std::to_string(earlier.index) + "), which uses " + std::to_string(earlier.first) + "-" +
                    std::to_string(earlier.last) + "; expected each fixture its own channels");
      }
      if (!reach || reach->universe != s.universe || s.last > reach->last) reach = &s;
    }
  }

  void range(const std::string& ptr, const char* what, float v, const Range& r, const std::string& profile) {
    if (r.contains(v)) return;
    problem(ptr, std::string(what) + " " + num(v) + " is outside the range of profile \"" + profile + "\"; expected " +
                     num(r.min) + " to " + num(r.max));
  }

  void values(const std::string& p, const Cue& cue) {
    for (const auto& [id, given] : cue.values) {
      // Palette values are checked against each fixture that plays them, at the cue that does.
      const CueValues v = resolveValues(show, id, given);
      const std::string vp = p + "/values/" + std::to_string(id);
      const FixtureDef* f = show.findFixture(id);
      if (!f) {
        problem(vp, "no fixture with id " + std::to_string(id) + "; expected the id of a fixture in /fixtures");
        continue;
      }
      const Profile* prof = profileOf(*f);
      if (!prof) continue;
      if (v.panDeg) range(vp + "/pan", "pan", *v.panDeg, prof->panDeg, f->profile);
      if (v.tiltDeg) range(vp + "/tilt", "tilt", *v.tiltDeg, prof->tiltDeg, f->profile);
      if (v.zoomDeg) range(vp + "/zoom", "zoom", *v.zoomDeg, prof->zoomDeg, f->profile);
      if (v.gobo && !prof->findGobo(*v.gobo)) {
        std::vector<std::string> slots{"\"Open\""};
        if (!prof->goboWheels.empty())
          for (const WheelSlot& s : prof->goboWheels.front().slots)
            if (s.name != "Open") slots.push_back("\"" + s.name + "\"");
        problem(vp + "/gobo", "profile \"" + f->profile + "\" has no gobo slot \"" + *v.gobo +
                                  "\" on its first gobo wheel; expected one of: " + joinNames(slots));
      }
      for (const auto& [k, cv] : v.cells)
        if (static_cast<size_t>(k) >= prof->cells.size())
          problem(vp + "/cells/" + std::to_string(k + 1),
                  "profile \"" + f->profile + "\" has " +
                      (prof->cells.empty() ? std::string("no cells") : std::to_string(prof->cells.size()) + " cells") +
                      "; expected a cell number from 1 to the profile's cell count (docs/cells.md)");
      optics(vp, v, *prof, f->profile);
    }
  }

  // The optics a profile must declare (docs/show-format.md): a cue cannot set what it lacks.
  void optics(const std::string& vp, const CueValues& v, const Profile& prof, const std::string& name) {
    if (v.frost && *v.frost > 0.0f && !prof.hasFrost)
      problem(vp + "/frost", "profile \"" + name + "\" has no frost; expected no frost value (or 0)");
    if (v.gateFocus && !prof.hasGateFocus)
      problem(vp + "/focus", "profile \"" + name + "\" has no focus; expected no focus value");
    if (v.prism && *v.prism != "Open" && !prof.findPrism(*v.prism)) {
      std::vector<std::string> names{"\"Open\""};
      for (const PrismSpec& p : prof.prisms) names.push_back("\"" + p.name + "\"");
      problem(vp + "/prism", "profile \"" + name + "\" has no prism \"" + *v.prism + "\"; expected one of: " + joinNames(names));
    }
    if (v.prismRotationDeg && prof.prisms.empty())
      problem(vp + "/prism_rotation", "profile \"" + name + "\" has no prism; expected no prism_rotation");
    if (v.prismSpinDegS && prof.prisms.empty())
      problem(vp + "/prism_spin", "profile \"" + name + "\" has no prism; expected no prism_spin");
    if (v.goboSpinDegS && prof.goboWheels.empty())
      problem(vp + "/gobo_spin", "profile \"" + name + "\" has no gobo wheel; expected no gobo_spin");
    if (v.gobo2 && !prof.findGobo(*v.gobo2, 1)) {
      std::vector<std::string> slots{"\"Open\""};
      if (prof.goboWheels.size() > 1)
        for (const WheelSlot& s : prof.goboWheels[1].slots)
          if (s.name != "Open") slots.push_back("\"" + s.name + "\"");
      problem(vp + "/gobo2", "profile \"" + name + "\" has no gobo slot \"" + *v.gobo2 +
                                 "\" on its second gobo wheel; expected one of: " + joinNames(slots));
    }
    if (v.color2 && *v.color2 != "Open") {
      bool found = false;
      std::vector<std::string> slots{"\"Open\""};
      if (prof.colorWheels.size() > 1)
        for (const WheelSlot& s : prof.colorWheels[1].slots) {
          found = found || s.name == *v.color2;
          if (s.name != "Open") slots.push_back("\"" + s.name + "\"");
        }
      if (!found)
        problem(vp + "/color2", "profile \"" + name + "\" has no colour slot \"" + *v.color2 +
                                    "\" on its second colour wheel; expected one of: " + joinNames(slots));
    }
    if (v.animation && !prof.findAnimation(*v.animation)) {
      std::vector<std::string> slots{"\"Open\""};
      if (!prof.animationWheels.empty())
        for (const WheelSlot& s : prof.animationWheels[0].slots)
          if (s.name != "Open") slots.push_back("\"" + s.name + "\"");
      problem(vp + "/animation", "profile \"" + name + "\" has no animation slot \"" + *v.animation + "\"; expected one of: " +
                                     joinNames(slots));
    }
    for (auto [key, set] : {std::pair{"animation_rotation", v.animationRotationDeg.has_value()},
                            std::pair{"animation_spin", v.animationSpinDegS.has_value()}})
      if (set && prof.animationWheels.empty())
        problem(vp + "/" + key, "profile \"" + name + "\" has no animation wheel; expected no " + key);
    for (auto [key, set] : {std::pair{"gobo2_rotation", v.gobo2RotationDeg.has_value()}, std::pair{"gobo2_spin", v.gobo2SpinDegS.has_value()}})
      if (set && prof.goboWheels.size() < 2)
        problem(vp + "/" + key, "profile \"" + name + "\" has no second gobo wheel; expected no " + key);
    const bool bladesIn = v.blades && std::any_of(v.blades->begin(), v.blades->end(),
                                                  [](const glm::vec2& e) { return e.x > 0.0f || e.y > 0.0f; });
    if (bladesIn && !prof.hasBlades)
      problem(vp + "/blades", "profile \"" + name + "\" has no framing blades; expected no blades (or all [0, 0])");
    if (v.bladeRotationDeg && !prof.hasBlades)
      problem(vp + "/blade_rotation", "profile \"" + name + "\" has no framing blades; expected no blade_rotation");
  }

  void cueLists() {
    std::map<std::string, size_t> names;
    for (size_t li = 0; li < show.cueLists.size(); ++li) {
      const CueList& l = show.cueLists[li];
      const std::string lp = "/cue_lists/" + std::to_string(li);
      if (!l.name.empty()) {
        auto [it, fresh] = names.emplace(l.name, li);
        if (!fresh)
          problem(lp + "/name", "cue list name \"" + l.name + "\" is already used by /cue_lists/" +
                                    std::to_string(it->second) + "; expected unique names");
      }
      std::optional<size_t> previous;  // the last cue with a readable number
      std::optional<size_t> previousTimecode;  // the last cue with a timecode
      for (size_t ci = 0; ci < l.cues.size(); ++ci) {
        const Cue& c = l.cues[ci];
        const std::string p = lp + "/cues/" + std::to_string(ci);
        if (!c.number.empty()) {
          if (previous) {
            const Cue& b = l.cues[*previous];
            int order = compareCueNumbers(b.number, c.number);
            const std::string where = lp + "/cues/" + std::to_string(*previous);
            if (order == 0)
              problem(p + "/number", "cue number \"" + c.number + "\" repeats cue \"" + b.number + "\" (" + where +
                                         "); expected each number once");
            else if (order > 0)
              problem(p + "/number", "cue number \"" + c.number + "\" comes after cue \"" + b.number + "\" (" + where +
                                         "); expected numbers that increase down the list");
          }
          previous = ci;
        }
        // Timecode chases to the last cue at or before the time, so the times must rise with the list.
        if (!c.timecode.empty()) {
          const auto tc = parseTimecode(c.timecode);
          if (!tc) {
            problem(p + "/timecode", "\"" + c.timecode + "\" is not a timecode; expected \"hh:mm:ss:ff\" within a day");
          } else if (previousTimecode) {
            const Cue& b = l.cues[*previousTimecode];
            if (auto tb = parseTimecode(b.timecode); tb && *tc <= *tb)
              problem(p + "/timecode", "timecode " + c.timecode + " is not after cue \"" + b.number + "\"'s " + b.timecode +
                                           " (" + lp + "/cues/" + std::to_string(*previousTimecode) +
                                           "); expected timecodes that increase down the list");
          }
          if (tc) previousTimecode = ci;
        }
        values(p, c);
      }
    }
  }
};

}  // namespace

std::vector<Error> validateShow(const Show& show, const ProfileSet& profiles) {
  Checker c{show, profiles, {}};
  c.venue();
  c.cameras();
  c.fixtures();
  c.cueLists();
  std::vector<Error> refs = checkGroupsAndPalettes(show);
  c.problems.insert(c.problems.end(), refs.begin(), refs.end());
  return std::move(c.problems);
}

namespace {
CheckedShow checkShowText(std::string_view text, const std::filesystem::path& file) {
  ShowParse parse = parseShowText(text, file);
  CheckedShow out{.show = std::move(parse.show), .profiles = {}, .problems = std::move(parse.problems)};
  ProfileLoad load = loadProfilesAll(out.show);
  out.problems.insert(out.problems.end(), load.problems.begin(), load.problems.end());
  std::vector<Error> cross = validateShow(out.show, load.profiles);
  out.problems.insert(out.problems.end(), cross.begin(), cross.end());
  out.profiles = std::move(load.profiles);
  out.show.stamp = stampOf(text);
  return out;
}
}  // namespace

CheckedShow checkShowFile(const std::filesystem::path& file) {
  auto bytes = readShowBytes(file);
  if (!bytes) return CheckedShow{.show = {}, .profiles = {}, .problems = {bytes.error()}};
  return checkShowText(*bytes, file);
}

std::vector<Error> validateShowFile(const std::filesystem::path& file) { return checkShowFile(file).problems; }

std::vector<Error> validateShowText(std::string_view text, const std::filesystem::path& file) {
  return checkShowText(text, file).problems;
}

}  // namespace haze
