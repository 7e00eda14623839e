// `haze bench --study`: the virtual-plane accuracy study of Dobashi et al. redone against the
// CPU reference (docs/rendering.md, "The accuracy study"), and the statistics the bench reports.
#pragma once

#include <vector>

namespace haze {

// The study's table on stdout (markdown); 1 with one line on stderr when a renderer fails.
// Needs a current GL context.
int runStudy(int width, int height);

// The median of a list of times (0 for none).
double medianOf(std::vector<double> values);

}  // namespace haze
