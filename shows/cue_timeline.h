// A cue range played as on stage, for a video (`haze render --video`, docs/shows.md "Playing a
// cue list to video"): GO on the first cue at 0 s; a cue with a follow makes the next one GO by
// itself (CuePlayer's rule); after a cue without one the operator waits `hold` seconds from the
// end of its delay and fade, then presses GO. The video ends `hold` after the last cue's fade
// (or when its follow would GO the cue after the range).
#pragma once

#include <vector>

#include "shows/show.h"

namespace haze {

struct CueGo {
  size_t cueIndex = 0;
  double atS = 0.0;
  bool byFollow = false;  // the player fires it from the cue before; the operator does not press GO
};

struct CueTimeline {
  std::vector<CueGo> gos;  // in time order, one per cue of the range
  double endS = 0.0;
};

// from <= to < list.cues.size(); holdS >= 0.
// The show gives each cue's full duration (cueDurationS: fans and part times included).
CueTimeline playCueRange(const Show& show, const CueList& list, size_t from, size_t to, double holdS);

}  // namespace haze
