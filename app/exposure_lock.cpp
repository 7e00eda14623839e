// meterCueList (see exposure_lock.h).
#include "app/exposure_lock.h"

#include <algorithm>

#include "shows/hazer_levels.h"
#include "shows/playback.h"

namespace haze {

Result<ListMetering> meterCueList(RenderSession& session, const Show& show, const ProfileSet& profiles,
                                  const CueList& list, size_t from, size_t to) {
  ListMetering out;
  bool any = false;
  to = std::min(to, list.cues.empty() ? 0 : list.cues.size() - 1);
  for (size_t i = from; i <= to && i < list.cues.size(); ++i) {
    session.setHazers(hazerSchedule(show, {{&list, i}}, {}));
    if (Status s = session.draw(show, profiles, trackedState(show, profiles, list, i)); !s) return s.error();
    // The lowest EV is the brightest cue: the exposure that keeps its highlights keeps every cue's.
    const float ev = session.meteredEv();
    if (!any || ev < out.meteredEv) out = {.meteredEv = ev, .cue = i};
    any = true;
  }
  return out;
}

}  // namespace haze
