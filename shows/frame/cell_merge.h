// Merged cells (docs/cells.md, "Cost"): the lit cells of one fixture that share a light map (the
// same opticsKey: photometry, zoom, gobo, iris, frost, blades) drawn as one beam. The sum of their
// light has the same angular shape and colour, sum of dimmer x colour; only where it leaves from
// moves, to the cells' light-weighted centre, and the lens disc grows to cover them.
#pragma once

#include <vector>

#include "shows/scene/frame_state.h"

namespace haze {

// beams: one fixture's beams (all with the same head frame); groups of equal opticsKey become one.
void mergeCellBeams(std::vector<BeamState>& beams);

}  // namespace haze
