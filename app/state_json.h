// The stage state as JSON, one shape for `haze state --json` and `haze live --state-json`:
// {"<fixture id>": {"intensity", "pan", "tilt", "color", "zoom", "gobo", "gobo_rotation", "iris"}},
// zoom falling back to the profile's field angle (null when neither is known).
#pragma once

#include <nlohmann/json.hpp>

#include "shows/playback.h"
#include "shows/show.h"

namespace haze {

nlohmann::ordered_json stageStateJson(const Show& show, const ProfileSet& profiles, const StageState& state);

}  // namespace haze
