// Every edit the GUI makes to a show, as an undoable command for EditHistory (shows/edit/edit_history.h):
// fixtures (place, delete, move, rotate, rename, patch), the programmer, cues (record, update,
// delete, renumber, label, times) and the atmosphere. Each checks its input and returns an Error
// instead of changing anything when the edit cannot be made.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "shows/edit/edit_history.h"

namespace haze {

// --- Look-ups the GUI also wants before it edits. ---

// The id a newly placed fixture gets: one more than the largest id (1 in an empty show).
int nextFixtureId(const Show& show);
// The DMX footprint of a fixture's mode: an Error when the profile or mode is unknown.
Result<int> modeFootprint(const ProfileSet& profiles, const std::string& profile, const std::string& mode);
// The lowest address in `universe` where `footprint` slots are free of every patched fixture
// (other than `ignoreId`), or an Error when the universe has no such gap.
Result<int> nextFreeAddress(const Show& show, const ProfileSet& profiles, int universe, int footprint,
                            int ignoreId = 0);

// --- Fixtures. ---

// Adds a profile to the show's library under a new key (ShowDocument::addProfileFile reads the
// file first; the document keeps its loaded profiles in step with Show::profiles).
std::unique_ptr<EditCommand> addProfile(std::string key, ProfileRef ref);

struct FixturePlacement {
  std::string profile;  // key of Show::profiles (and of the ProfileSet)
  std::string mode;     // "" = the profile's first mode
  glm::vec3 positionM{0.0f};
  glm::vec3 rotationDeg{0.0f};
  std::string name;     // "" = "<profile name> <id>"
  std::optional<int> universe = 1;  // patched at the next free address there; empty = unpatched
};
// Adds a fixture with id nextFixtureId(show).
std::unique_ptr<EditCommand> placeFixture(FixturePlacement placement);
// Removes the fixtures, their values in every cue and in the programmer.
std::unique_ptr<EditCommand> deleteFixtures(std::vector<int> ids);
// Merge-able with the next move/rotate of the same fixture (a drag).
std::unique_ptr<EditCommand> moveFixture(int id, glm::vec3 positionM);
std::unique_ptr<EditCommand> rotateFixture(int id, glm::vec3 rotationDeg);
std::unique_ptr<EditCommand> renameFixture(int id, std::string name);
// Sets the mode ("" keeps the current one) and the patch (empty = unpatched). The footprint must
// fit in 1..512 without overlapping another patched fixture.
std::unique_ptr<EditCommand> patchFixture(int id, std::optional<Patch> patch, std::string mode = "");

// --- The programmer. ---

// Lays the set attributes of each entry over that fixture's programmer values. Merge-able with
// the next setProgrammer on the same fixtures (dragging a pan/tilt handle or a fader).
std::unique_ptr<EditCommand> setProgrammer(std::map<int, CueValues> values);
// Takes the fixtures out of the programmer (empty list: all of them).
std::unique_ptr<EditCommand> clearProgrammer(std::vector<int> ids = {});

// --- Cues. A list is named by CueList::name ("" = the first list), a cue by its number. ---

struct CueRecord {
  std::string list;      // created (named list, or "Main" for "") when the show has no such list
  std::string after;     // the new cue goes after this cue; "" = ahead of the first cue
  std::string number;    // "" = chosen between the neighbours (cueNumberBetween)
  std::string label;
};
// A new cue holding the programmer's values that differ from the tracked state of the cue before
// it (or from the defaults at the start): tracking, so the cue stores only what changes. The
// programmer keeps its values (clear it with clearProgrammer).
std::unique_ptr<EditCommand> recordCue(CueRecord record);
// The same from `look` (fixture id -> its values, e.g. what DMX put on stage) instead of the
// programmer, which stays as it is.
std::unique_ptr<EditCommand> recordLook(CueRecord record, std::map<int, CueValues> look);
// Folds the programmer into an existing cue: a value equal to the tracked state before the cue is
// dropped from it (the cue then tracks it, with the same look), any other value is set.
std::unique_ptr<EditCommand> updateCue(std::string list, std::string number);
std::unique_ptr<EditCommand> deleteCue(std::string list, std::string number);
// Gives a cue a new, unused number; the cue moves to where that number sorts in the list.
std::unique_ptr<EditCommand> renumberCue(std::string list, std::string number, std::string newNumber);
std::unique_ptr<EditCommand> labelCue(std::string list, std::string number, std::string label);

struct CueTimes {
  double fadeS = 0.0;
  double delayS = 0.0;
  std::optional<double> followS;  // empty = wait for the operator
};
std::unique_ptr<EditCommand> setCueTimes(std::string list, std::string number, CueTimes times);

// --- Groups and palettes (docs/gui.md, "Console commands"). Names are compared in any case. ---

// A new palette from the programmer: for each fixture it holds, its values of `kind` (palettes
// resolved). No kind: position, colour or beam when the programmer holds values of that kind
// alone, else "all". The fixtures recorded then refer to the new palette in the programmer.
std::unique_ptr<EditCommand> recordPalette(std::string name, std::optional<PaletteKind> kind);
// Lays the programmer's values of the palette's kind into its per-fixture entries (only what
// differs from what it gives now); the fixtures then refer to it in the programmer.
std::unique_ptr<EditCommand> updatePalette(std::string name);
// Refused while a cue or the programmer refers to the palette.
std::unique_ptr<EditCommand> deletePalette(std::string name);
// A new group of `fixtures`, in that order.
std::unique_ptr<EditCommand> recordGroup(std::string name, std::vector<int> fixtures);
// Refused while a palette, a fan or an effect names the group.
std::unique_ptr<EditCommand> deleteGroup(std::string name);
// What recordPalette without a kind picks for this programmer, and the attributes a kind holds
// (for messages).
PaletteKind paletteKindOfProgrammer(const Show& show, const Programmer& programmer);
std::string paletteKindAttributes(PaletteKind kind);

// --- The show. ---

// Checked as the show format does: scattering and absorption >= 0, phase hazy|isotropic|hg,
// g in (-1, 1), ambient and background >= 0.
std::unique_ptr<EditCommand> setAtmosphere(AtmosphereDef atmosphere);

}  // namespace haze
