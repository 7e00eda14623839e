// What a cue changes, as the review sheet lists it for the desk (docs/output.md, "Review
// sheet"): fixtures of one type with the same change as a range, "11-20 Alpha Spot @ 70 %,
// palette Blue, gobo Spokes"; palette names where the cue takes the values from a palette;
// colours as sRGB codes (#ff8800) rather than linear filters.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "shows/show.h"

namespace haze {

// `before` and `after`: stageStateJson of the tracked states before and at the cue. One line per
// run of fixtures (same profile, same change), in order of their first fixture id.
std::vector<std::string> sheetChanges(const Show& show, const ProfileSet& profiles, const Cue& cue,
                                      const nlohmann::ordered_json& before, const nlohmann::ordered_json& after);

// "#ff8800": a linear RGB filter as the sRGB code a colour picker shows.
std::string srgbCode(float r, float g, float b);

}  // namespace haze
