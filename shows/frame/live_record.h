// `haze live --record-cue N`: the stage haze resolved from DMX written into cue N of the show
// and saved. Recording works as the GUI's Record (Ctrl+R): a new cue keeps only the values that
// differ from the tracked state before it; an existing cue N is updated the same way (values
// equal to the state before it are dropped, others set). The save is the shows library's safe
// save: a temporary file renamed over the show, the old one kept as .bak, and a refusal when the
// file changed on disk since haze loaded it.
#pragma once

#include <set>
#include <string>

#include "fixtures/core/result.h"
#include "shows/playback.h"
#include "shows/show.h"

namespace haze {

struct LiveRecord {
  std::string list;    // the cue list's name; "" = the first list ("Main" is made if none)
  std::string number;  // the cue number
  std::string label;
};

// Records `fixtures`' attributes from `stage` and saves the show to show.file. Returns a line for
// the log ("recorded cue 10 ...").
Result<std::string> recordLiveCue(Show& show, const ProfileSet& profiles, const StageState& stage,
                                  const std::set<int>& fixtures, const LiveRecord& record);

}  // namespace haze
