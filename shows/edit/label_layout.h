// Where the viewport draws the labels of selected fixtures so that none covers another, and
// which fixtures the Fixtures and Patch tabs list, in which order. Pure geometry and sorting:
// the GUI (app/gui/gui_viewport.cpp, gui_fixtures.cpp, gui_patch.cpp) draws what these return,
// and the unit tests check them without a window (docs/gui-commands.md, "Fixture identity").
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "shows/show.h"

namespace haze {

struct LabelBox {
  float x = 0, y = 0, w = 0, h = 0;  // screen pixels, y down
  bool intersects(const LabelBox& o) const { return x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h; }
};

struct PlacedLabel {
  int fixture = 0;
  glm::vec2 anchor{0.0f};  // the marker the label names
  LabelBox box;            // where it is drawn
  bool moved = false;      // pushed off its first place: the GUI draws a leader line to the anchor
};

struct LabelRequest {
  int fixture = 0;
  glm::vec2 anchor{0.0f};
  glm::vec2 sizePx{0.0f};  // the text's size
};

// Greedy declutter: in the order given (the GUI passes fixture id order, so the same selection
// always lays out the same way), each label goes right of its marker, vertically centred, and
// is pushed down in steps of its own height (plus a gap) until its box meets no label placed
// before it. Boxes never intersect; a label pushed past maxPushPx from its first place keeps
// that place anyway (a leader line that long would be harder to read than an overlap, and it
// takes about 40 labels stacked at one marker to get there).
std::vector<PlacedLabel> placeLabels(const std::vector<LabelRequest>& labels, float maxPushPx = 2000.0f);

// "2.101": a fixture's universe.address, or "-" when it is not patched.
std::string patchText(const FixtureDef& fixture);

// The fixtures a tab lists: sorted by id, kept when the filter (case-insensitive, blanks at the
// ends ignored) is empty or found in the id, the name, the profile, the mode or the
// universe.address ("2." lists universe 2; "Spot" lists the spots). Pointers into show.fixtures.
std::vector<const FixtureDef*> listedFixtures(const Show& show, const std::string& filter);

}  // namespace haze
