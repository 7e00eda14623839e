#include "shows/cue_timeline.h"

#include "shows/playback.h"

namespace haze {

CueTimeline playCueRange(const Show& show, const CueList& list, size_t from, size_t to, double holdS) {
  CueTimeline timeline;
  double at = 0.0;
  bool byFollow = false;
  for (size_t i = from; i <= to && i < list.cues.size(); ++i) {
    const Cue& cue = list.cues[i];
    timeline.gos.push_back({.cueIndex = i, .atS = at, .byFollow = byFollow});
    const double done = at + cueDurationS(show, cue);
    // CuePlayer arms no follow on the last cue of the list.
    byFollow = cue.followS.has_value() && i + 1 < list.cues.size();
    at = done + (byFollow ? *cue.followS : holdS);
  }
  timeline.endS = at;
  return timeline;
}

}  // namespace haze
