// Cue numbers: decimal strings ("1", "1.5", "10") compared as numbers, exactly, without floating
// point, so that "1.10" and "1.1" are the same cue and "10" comes after "9".
#pragma once

#include <string_view>

namespace haze {

// True for one or more digits, optionally followed by '.' and one or more digits.
bool isCueNumber(std::string_view s);
// <0, 0, >0 as a is before, the same as, or after b. Both must satisfy isCueNumber.
int compareCueNumbers(std::string_view a, std::string_view b);

}  // namespace haze
