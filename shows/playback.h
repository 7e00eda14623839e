// Cue playback, the tracking model of show-format.md. The pure face: the state of every fixture
// at a moment after GO. (The clock-driven player for the GUI and live playback sits beside it.)
#pragma once

#include <map>
#include <string>

#include "fixtures/attributes.h"
#include "fixtures/result.h"
#include "shows/show.h"

namespace haze {

using StageState = std::map<int, Attributes>;  // fixture id -> attributes

// The tracked full state of cue cueIndex (all fixtures of the show, defaults where unset).
StageState trackedState(const Show& show, const ProfileSet& profiles, const CueList& list,
                        size_t cueIndex);
// The state secondsSinceGo after GO into cue cueIndex from the full state of the cue before it.
StageState stateAt(const Show& show, const ProfileSet& profiles, const CueList& list,
                   size_t cueIndex, double secondsSinceGo);
// Index of the cue with this number ("1", "1.5"), or an error naming the list.
Result<size_t> findCue(const CueList& list, const std::string& number);

}  // namespace haze
