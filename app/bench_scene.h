// The bench scene: a stage (deck, back wall, side walls, columns and a hanging panel that cut
// shadows) with N spots on two truss lines, all in haze, seen from the house. Built in code so
// `haze bench` needs no files; the same scene serves the reference comparison.
#pragma once

#include "renderer/scene/frame_state.h"
#include "renderer/scene/venue.h"

namespace haze {

Venue benchVenue();
FrameState benchFrame(int fixtures);

}  // namespace haze
