// Change fixture type: selected fixtures get another profile and mode, keeping their id, name,
// position, orientation and patch start; every value the show holds for them (cues, palettes,
// the programmer) is mapped attribute by attribute onto what the new type can do
// (docs/fixtures.md, "Changing a fixture's type"). One undo step.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "shows/edit/edit_history.h"

namespace haze {

struct ChangeTypeRequest {
  std::vector<int> fixtures;
  std::string profileKey;                  // the new type's key in Show::profiles
  std::shared_ptr<const Profile> profile;  // the new type, loaded
  ProfileRef ref;                          // added under profileKey when the show has no such key
  std::string mode;                        // "" = the new type's first mode
};

// What the change did not carry over as it was: one line per value ("cue 3 fixture 11: pan 300
// clamped to 270"), filled by apply.
struct ChangeTypeReport {
  std::vector<std::string> lines;
  int valuesMapped = 0;  // fixture entries (cues, palettes, programmer) gone through
};

// Refused, with the list, when a new footprint overlaps another patched fixture or runs past 512.
std::unique_ptr<EditCommand> changeFixtureType(ChangeTypeRequest request, std::shared_ptr<ChangeTypeReport> report = nullptr);

// The values one fixture's entry holds, mapped onto what profile `to` can do; what changed on the
// way is appended to `notes` prefixed with `where` ("cue 3 fixture 11").
CueValues mapValuesToProfile(const CueValues& values, const Profile& to, const std::string& where, std::vector<std::string>& notes);

}  // namespace haze
