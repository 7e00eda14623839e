// Rendering a show's state to an image file: the one path shared by `haze render`, `haze live
// --render` and the tests. Builds the FrameState from the show, its profiles and a stage state.
#pragma once

#include <filesystem>
#include <string>

#include "fixtures/core/result.h"
#include "shows/playback.h"
#include "shows/show.h"

namespace haze {

enum class Quality { Draft, Default, High, Reference };

struct RenderJobOptions {
  std::string camera;      // camera name; "" = the show's first camera
  int width = 1280;
  int height = 720;
  Quality quality = Quality::Default;
};

// Writes out as .png (exposure, tone curve, sRGB) or .pfm (radiometric float).
Status renderStateToFile(const Show& show, const ProfileSet& profiles, const StageState& state,
                         const RenderJobOptions& options, const std::filesystem::path& out);

}  // namespace haze
