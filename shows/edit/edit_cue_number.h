// Choosing a cue number for a cue recorded between two others ("1" and "2" -> "1.5"), exactly in
// decimal so that numbers never pick up binary rounding ("1.1" + ... never becomes "1.0999").
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "fixtures/core/result.h"

namespace haze {

// The number for a new cue after `before` and ahead of `after` (both isCueNumber):
// - both given: the shortest decimal strictly between them, the middle one among those of that
//   length ("1","2" -> "1.5"; "1","1.5" -> "1.2"; "1.1","1.2" -> "1.15");
// - no `after` (recording at the end): the next whole number ("3" -> "4", "3.5" -> "4");
// - no `before` (recording ahead of the first cue): between 0 and `after` ("1" -> "0.5").
// An error when there is no room (after <= before, or ahead of cue "0") or a number is malformed.
Result<std::string> cueNumberBetween(std::optional<std::string_view> before,
                                     std::optional<std::string_view> after);

}  // namespace haze
