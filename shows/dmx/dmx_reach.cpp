// dmxReach (see dmx_reach.h): the same mode choice and the same intensity rule as the decoder
// (fixtures/dmx_decode.h), said in words.
#include "shows/dmx/dmx_reach.h"

#include <algorithm>
#include <map>

namespace haze {

const DmxMode* dmxModeOf(const FixtureDef& fixture, const ProfileSet& profiles, std::string* whyNot) {
  auto why = [whyNot](std::string text) -> const DmxMode* {
    if (whyNot) *whyNot = std::move(text);
    return nullptr;
  };
  auto it = profiles.find(fixture.profile);
  if (it == profiles.end() || !it->second) return why("its profile \"" + fixture.profile + "\" did not load");
  const Profile& profile = *it->second;
  if (profile.modes.empty()) return why("its profile \"" + fixture.profile + "\" has no DMX modes");
  if (fixture.mode.empty()) return &profile.modes.front();
  for (const DmxMode& m : profile.modes)
    if (m.name == fixture.mode) return &m;
  return why("its profile \"" + fixture.profile + "\" has no DMX mode \"" + fixture.mode + "\"");
}

namespace {

bool isRgb(DmxAttribute a) {
  return a == DmxAttribute::Red || a == DmxAttribute::Green || a == DmxAttribute::Blue || a == DmxAttribute::White;
}

}  // namespace

std::vector<UniverseReach> dmxReach(const Show& show, const ProfileSet& profiles) {
  std::map<int, UniverseReach> byUniverse;
  for (const FixtureDef& f : show.fixtures) {
    if (!f.patch) continue;
    UniverseReach& u = byUniverse[f.patch->universe];
    u.universe = f.patch->universe;
    std::string why;
    const DmxMode* mode = dmxModeOf(f, profiles, &why);
    if (!mode) {
      u.undriven.push_back({f.id, why});
      continue;
    }
    const auto has = [mode](auto pred) {
      return std::any_of(mode->channels.begin(), mode->channels.end(), [&](const DmxChannel& c) { return pred(c.attribute); });
    };
    if (!has([](DmxAttribute a) { return a != DmxAttribute::None; })) {
      u.undriven.push_back({f.id, "none of the " + std::to_string(mode->channels.size()) + " channels of mode \"" +
                                      mode->name + "\" is one haze reads (haze fixture info lists them)"});
      continue;
    }
    u.driven.push_back(f.id);
    if (!has([](DmxAttribute a) { return a == DmxAttribute::Intensity; }) && !has(isRgb))
      u.atFull.push_back({f.id, "mode \"" + mode->name + "\" has no dimmer channel"});
  }
  std::vector<UniverseReach> out;
  for (auto& [universe, reach] : byUniverse) {
    std::sort(reach.driven.begin(), reach.driven.end());
    out.push_back(std::move(reach));
  }
  return out;
}

}  // namespace haze
