// Show-wide defaults for programming (docs/show-format.md, "default_fade"): the fade a newly
// recorded cue gets, as a console's default cue time.
#pragma once

#include <memory>

#include "shows/edit/edit_history.h"

namespace haze {

// Sets Show::defaultFadeS, 0..3600 s; recordCue and recordLook give new cues that fade.
std::unique_ptr<EditCommand> setDefaultFade(double seconds);

}  // namespace haze
