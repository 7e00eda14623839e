// Fixture ids as a console writes them: "1-3, 5, 7-9".
#pragma once

#include <string>
#include <vector>

namespace haze {

// The ids sorted, each run of consecutive ids as "a-b", joined by ", ".
std::string idRanges(std::vector<int> ids);

}  // namespace haze
