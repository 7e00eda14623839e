// Hazers in cues (docs/shows.md, "Hazers in cues"): the output and fan levels a cue list's cues
// give the hazers of the show's density field, tracked like the fixtures' values, and the
// schedule they make for the density simulation as cues GO.
#pragma once

#include <map>
#include <vector>

#include "atmosphere/hazer_schedule.h"
#include "shows/show.h"

namespace haze {

// The levels the cues of `list` up to cueIndex set, by hazer number (from 1): output and fan
// each from the last cue that set it. Hazers no cue of the list sets are absent.
std::map<int, HazerCueDef> trackedHazers(const CueList& list, size_t cueIndex);

// One cue of a list on stage, or going at a playback time.
struct HazerCue {
  const CueList* list = nullptr;
  size_t cueIndex = 0;
  double goS = 0.0;  // playback seconds of its GO (ignored for cues on stage from the start)
};

// The schedule of the show's hazers in simulation time (warmup + playback time, docs/shows.md
// "Density"). The tracked levels of the cues in `onStage` hold from the start (in order: a later
// list's values take over), then each GO in `gos` (in time order) fades the hazers its list sets
// from where they are to its tracked levels over the cue's delay and fade, as a later GO takes
// over an attribute (LTP). Empty when no cue sets a hazer: every hazer runs at full output.
HazerSchedule hazerSchedule(const Show& show, const std::vector<HazerCue>& onStage, const std::vector<HazerCue>& gos);

}  // namespace haze
