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

// How far from the lens (metres) a fixture's cells must have become one beam for `auto` to draw
// them as one: their cones, each as wide as tan(F / 2) x this distance there, then overlap.
constexpr float kCellsOverlapWithinM = 1.0f;

// Whether `auto` draws a fixture's cells as one beam (docs/cells.md, "Cost"): all `cells` of its
// cells are lit and driven alike (the same photometry, dimmer and colour, as a wash run as one
// colour is), and they lie within tan(F / 2) x kCellsOverlapWithinM of their centre, so that
// their cones overlap from that distance on. Cells driven apart (a pixel effect, one cell dark or
// another colour) or spread wide (an LED bar of narrow beams) stay separate beams.
bool cellsActAsOne(const std::vector<BeamState>& beams, size_t cells);

}  // namespace haze
