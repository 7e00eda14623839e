// Rendering a show's state to an image file: the one path shared by `haze render`, `haze live
// --render` and the tests. Builds the FrameState from the show, its profiles and a stage state.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "fixtures/core/result.h"
#include "renderer/output/exr.h"
#include "shows/scene/exposure.h"
#include "shows/playback.h"
#include "shows/frame/frame_builder.h"
#include "shows/show.h"

namespace haze {

enum class Quality { Draft, Default, High, Reference };

struct RenderJobOptions {
  std::string camera;      // camera name; "" = the show's first camera
  int width = 1280;
  int height = 720;
  Quality quality = Quality::Default;
  // Over the camera's exposure (CameraDef::exposure), itself over auto at offset 0. A mode other
  // than the camera's drops the camera's EV too: an absolute EV means nothing as an offset.
  std::optional<ExposureMode> exposureMode;
  std::optional<float> exposureEv;
  float bloom = 0.0f;  // PNG only
  CellBeams cells = CellBeams::Auto;  // docs/cells.md, "Cost": a fixture's cells as one beam or one per cell
  bool bodies = true;       // the fixtures' housings (docs/fixtures.md, "Bodies"); --no-bodies
  std::optional<bool> softShadows;  // --shadows soft|hard; none: the show's atmosphere.shadows
  ExrPixel exrPixel = ExrPixel::Half;  // EXR only
  // Visible dust (docs/rendering.md, "Particles"): --particles / --no-particles; none: a PNG
  // follows the show's atmosphere.particles, a PFM or EXR stays radiometric (no particles).
  std::optional<bool> particles;
  bool progress = false;  // --progress: report even when stderr is not a terminal (app/progress.h)
};

// The exposure a PNG of this show gets with these options.
ExposureChoice exposureChoiceFor(const Show& show, const RenderJobOptions& options);
// "auto" or "manual" (the command lines' --exposure-mode); "" leaves the mode unset.
std::optional<ExposureMode> parseExposureMode(const std::string& name);

// Writes out as .png (exposure, tone curve, sRGB), .pfm or .exr (radiometric).
Status renderStateToFile(const Show& show, const ProfileSet& profiles, const StageState& state,
                         const RenderJobOptions& options, const std::filesystem::path& out);

}  // namespace haze
