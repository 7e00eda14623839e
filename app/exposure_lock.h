// One exposure for a whole cue list (docs/rendering.md, "Exposure"): a video or an --all-cues run
// is metered once, on the brightest of its cues, so that a fade darkens the picture as it does
// the stage and the balance between cues shows, instead of the meter chasing every frame.
#pragma once

#include "app/render_session.h"
#include "fixtures/core/result.h"
#include "shows/show.h"

namespace haze {

struct ListMetering {
  float meteredEv = 0.0f;  // what the meter said of the brightest cue (the lowest EV)
  size_t cue = 0;          // which cue that was (an index into the list)
};

// Draws the full state of each cue from..to of `list` (its fades done, its hazers on) and meters
// it; the brightest sets the exposure. Leaves the session's hazers for the caller to set.
Result<ListMetering> meterCueList(RenderSession& session, const Show& show, const ProfileSet& profiles,
                                  const CueList& list, size_t from, size_t to);

}  // namespace haze
