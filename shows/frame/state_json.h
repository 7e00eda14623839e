// The stage state as JSON, one shape for `haze state --json` and `haze live --state-json`:
// {"<fixture id>": {"intensity", "pan", "tilt", "color", "zoom", "gobo", "gobo_rotation", "iris",
// "frost", "focus" (fixtures with one), "prism", "prism_rotation", "blades", "blade_rotation", "shutter"[, "gate"]}}, zoom
// falling back to the profile's field angle (null when neither is known). With gateAtS, "gate"
// is the shutter's s(t) at that time on the playback clock (docs/show-format.md, "Strobe").
// "gobo2", "gobo2_rotation" and the spins ("gobo_spin" with "gobo_angle", the angle at gateAtS
// or 0...) only where they are not neutral.
#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include "shows/playback.h"
#include "shows/show.h"

namespace haze {

nlohmann::ordered_json stageStateJson(const Show& show, const ProfileSet& profiles, const StageState& state,
                                      std::optional<double> gateAtS = std::nullopt);

}  // namespace haze
