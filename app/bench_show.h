// `haze bench --show FILE [--cue N] [--camera NAME]`: a show's cue as the bench frame, so that rigs (a multi-cell
// wash against separate fixtures, docs/cells.md) can be timed like the synthetic stage.
#pragma once

#include <string>

#include "fixtures/core/result.h"
#include "shows/scene/frame_state.h"
#include "shows/scene/venue.h"
#include "shows/frame/frame_builder.h"
#include "shows/show.h"

namespace haze {

// The show (checked as haze validate checks it: app/command_line.h) and its venue (an empty stage when it names none) and the full state of cue `cue` of its
// first cue list ("" = the first cue), seen from camera `camera` ("" = the show's first); cells
// as FrameOptions::cells. fixtures: how many the show has.
Status loadBenchShow(const Show& show, const ProfileSet& profiles, const std::string& cue, const std::string& camera,
                     CellBeams cells, Venue& venue, FrameState& frame, int& fixtures);

}  // namespace haze
