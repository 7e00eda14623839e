// The frame-wide switches that the lighting programs have compiled in as #defines
// (shaders/interface.h, "Static features"): a density field, a sun, soft shadows and the phase
// function. Read from uniforms, each would cost every sample of every walk its code whether or
// not the frame has it, since llvmpipe runs both sides of a branch.
#pragma once

#include <string>
#include <vector>

#include "shaders/interface.h"

namespace haze {

struct ShaderFeatures {
  bool densityField = false;
  bool sun = false;
  bool softShadows = false;
  int phase = HAZE_PHASE_HAZY;

  std::vector<std::string> defines() const {
    std::vector<std::string> d{"STATIC_FEATURES", "PHASE_KIND " + std::to_string(phase)};
    if (densityField) d.emplace_back("DENSITY_FIELD");
    if (sun) d.emplace_back("SUN");
    if (softShadows) d.emplace_back("SOFT_SHADOWS");
    return d;
  }
};

}  // namespace haze
