// Show + profiles + a stage state -> the renderer's FrameState (camera, medium, one beam per
// lit fixture). This is the only place where shows meet the renderer.
#pragma once

#include <string>

#include "fixtures/core/result.h"
#include "renderer/scene/frame_state.h"
#include "shows/playback.h"
#include "shows/show.h"

namespace haze {

struct FrameOptions {
  // Cells of one fixture that share a light map drawn as one beam (docs/cells.md, "Cost").
  bool mergeCells = false;
};

// cameraName "" = the show's first camera (or a default view of the stage when it has none).
Result<FrameState> buildFrame(const Show& show, const ProfileSet& profiles, const StageState& state,
                              const std::string& cameraName, const FrameOptions& options = {});
// The renderer's shadow-map cache key of a pose (equal keys promise equal poses).
uint64_t poseCacheKey(const BeamPose& pose);

CameraState cameraState(const CameraDef& def);
MediumState mediumState(const AtmosphereDef& def);

}  // namespace haze
