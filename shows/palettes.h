// Groups and palettes (docs/show-format.md, "Groups and palettes"): what a palette gives one
// fixture, a cue entry with its palette references resolved, and the checks that every group and
// palette reference names something that exists. Palettes hold plain values only and groups hold
// fixture ids only, so no reference can be circular.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fixtures/core/result.h"
#include "shows/show.h"

namespace haze {

const char* paletteKindName(PaletteKind kind);  // "position", "color", "beam", "all"
std::optional<PaletteKind> paletteKindFromName(const std::string& name);

// Lays the values set in `over` onto `under` (set values win; cells merge per cell). References
// are not copied.
void layValues(CueValues& under, const CueValues& over);

// What a palette gives one fixture: its group entries for groups holding the fixture, laid over
// one another in the order of Show::groups, then its entry for the fixture itself. Empty when
// the palette has nothing for the fixture.
std::optional<CueValues> paletteValuesFor(const Show& show, const PaletteDef& palette, int fixtureId);

// A cue's entry for one fixture as it plays: its palettes (all, then position, colour, beam)
// laid under its own values. References that do not resolve add nothing; checkGroupsAndPalettes
// reports them and loadShow refuses such a show.
CueValues resolveValues(const Show& show, int fixtureId, const CueValues& values);

// The slot of `refs` that holds palettes of `kind`.
std::string& paletteSlot(PaletteRefs& refs, PaletteKind kind);
const std::string& paletteSlot(const PaletteRefs& refs, PaletteKind kind);

// The values of `v` that a palette of `kind` may hold (an "all" palette: every value). References
// are not copied.
CueValues valuesOfKind(PaletteKind kind, const CueValues& v);
// Resets in `v` every value that `mask` sets (cells per cell and value).
void clearValues(CueValues& v, const CueValues& mask);
// Resets in `v` every value equal to the one `ref` sets (what a palette already gives).
void dropEqualValues(CueValues& v, const CueValues& ref);
// Whether `v` sets any value (references aside).
bool hasValues(const CueValues& v);

// Makes `entry` (a programmer's or a cue's values for one fixture) refer to `palette` in the slot
// of its kind, as a console does when a palette is applied: the plain values the palette gives the
// fixture leave the entry, so the palette shows; an "all" palette also replaces the kind
// references whose values it overlaps. False (entry unchanged) when the palette has no value for
// the fixture.
bool applyPalette(const Show& show, CueValues& entry, int fixtureId, const PaletteDef& palette);

// Case-insensitive look-ups (the command line's names): the index or empty.
std::optional<size_t> paletteIndexNamed(const Show& show, const std::string& name);
std::optional<size_t> groupIndexNamed(const Show& show, const std::string& name);

// Where a palette is referred to ("cue 1 of Main", ...), and where a group is named (palettes,
// fans, effects); empty when nowhere.
std::vector<std::string> paletteUses(const Show& show, const std::string& name);
std::vector<std::string> groupUses(const Show& show, const std::string& name);

// The first attribute (its file name) of `values` that a palette of `kind` may not hold, or "".
std::string attributeOutsideKind(PaletteKind kind, const CueValues& values);

// Groups naming unknown fixtures or one fixture twice, repeated group or palette names, palettes
// naming unknown groups or fixtures or holding attributes outside their kind, and cue references
// to palettes that do not exist, are of another kind or have no value for the fixture. Each
// problem at its JSON pointer.
std::vector<Error> checkGroupsAndPalettes(const Show& show);

}  // namespace haze
