// The bench scene: a stage (deck, back wall, side walls, columns and a hanging panel that cut
// shadows) with N spots on truss lines, all in haze, seen from the house. Up to 16 fixtures it
// is two lines in a 20 m room; larger rigs get more and longer lines in a bigger room (an arena
// at 1000). Built in code so `haze bench` needs no files; the same scene serves the reference
// comparison.
#pragma once

#include "atmosphere/density_spec.h"
#include "shows/scene/frame_state.h"
#include "shows/scene/venue.h"

namespace haze {

Venue benchVenue(int fixtures);
FrameState benchFrame(int fixtures);
// `haze bench --move`'s motion: every beam of `frame` turned by `deg` about the vertical through
// its lens (a pan that leaves the lens, and so the venue's shadows, in place), its poseKey new.
FrameState turnedBeams(FrameState frame, float deg);
// `haze bench --density N`'s field: thin haze (D = 0.4) and one hazer at the deck's stage-left
// edge blowing across the stage, on N^3 cells over the venue, 60 s after it started.
DensitySpec benchDensity(int cellsPerSide);
// The accuracy study's scene (after Dobashi et al. 2000, figures 5 and 6): one spot in haze
// with a sphere in its beam, seen from the side, so the shadow shaft is in view.
Venue studyVenue();
FrameState studyFrame();

}  // namespace haze
