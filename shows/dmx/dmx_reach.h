// What live DMX can reach: for each universe of the patch, the fixtures its levels drive, the
// ones they cannot (and why), and the ones whose intensity no channel sets. `haze live` prints it
// at start (docs/live.md, "What the console drives"), so a fixture that ignores the console is
// explained before anyone wonders.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "shows/id_ranges.h"
#include "shows/show.h"

namespace haze {

// The DMX mode a patched fixture is decoded through: the one it names, or the profile's first when
// it names none. nullptr when there is none; `whyNot` then says why in a few words.
const DmxMode* dmxModeOf(const FixtureDef& fixture, const ProfileSet& profiles, std::string* whyNot = nullptr);

struct UniverseReach {
  int universe = 0;
  std::vector<int> driven;                            // fixture ids DMX drives, in id order
  std::vector<std::pair<int, std::string>> undriven;  // fixture id, why DMX cannot drive it
  std::vector<std::pair<int, std::string>> atFull;    // driven, but no channel sets the intensity
};

// One entry per patched universe, in universe order.
std::vector<UniverseReach> dmxReach(const Show& show, const ProfileSet& profiles);

}  // namespace haze
