// `haze bench --show FILE [--cue N]`: a show's cue as the bench frame, so that rigs (a multi-cell
// wash against separate fixtures, docs/cells.md) can be timed like the synthetic stage.
#pragma once

#include <string>

#include "fixtures/core/result.h"
#include "renderer/scene/frame_state.h"
#include "renderer/scene/venue.h"

namespace haze {

// The show's venue (an empty stage when it names none) and the full state of cue `cue` of its
// first cue list ("" = the first cue), seen from the show's first camera; mergeCells as
// FrameOptions::mergeCells.
Status loadBenchShow(const std::string& file, const std::string& cue, bool mergeCells, Venue& venue, FrameState& frame);

}  // namespace haze
