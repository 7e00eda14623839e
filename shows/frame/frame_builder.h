// Show + profiles + a stage state -> the renderer's FrameState (camera, medium, one beam per
// lit fixture). This is the only place where shows meet the renderer.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fixtures/core/result.h"
#include "shows/scene/frame_state.h"
#include "shows/playback.h"
#include "shows/show.h"

namespace haze {

// When a frame is taken, for the shutter (docs/physics.md, "Strobe"): its gate is averaged over
// [timeS, timeS + exposureS] of the playback clock. A frame without one is a still: a strobing
// shutter shows its mean (the duty).
struct FrameTime {
  double timeS = 0.0;
  double exposureS = 0.0;
};

// A multi-cell fixture's beams (docs/cells.md, "Cost"): one per lit cell, the cells that share
// a light map as one beam, or (auto) one beam where the cells act as one (cellsActAsOne in
// cell_merge.h) and one per cell where they do not.
enum class CellBeams { Separate, Merged, Auto };

// The --cells options' names, "auto", "separate" and "merged", and the modes they name (anything
// else is auto).
const std::vector<std::string>& cellBeamsNames();
CellBeams cellBeamsNamed(const std::string& name);
const char* cellBeamsName(CellBeams cells);

struct FrameOptions {
  CellBeams cells = CellBeams::Auto;
  std::optional<FrameTime> time;  // none: a still
  // The fixtures' housings (docs/fixtures.md, "Bodies"), dark fixtures' too.
  bool bodies = true;
  // The show clock the frame is built for (the playback time of --at, of a video frame, of the
  // GUI and live clocks): spinning wheels stand at rotation + spin * clockS (docs/physics.md, "Spin").
  double clockS = 0.0;
  // The medium's density field at the frame's time (shows/frame/atmosphere_field.h); none: uniform.
  std::shared_ptr<const DensityField> density;
  // Soft or hard shadows (--shadows); none: the show's atmosphere.shadows.
  std::optional<bool> softShadows;
  // Visible dust in the beams (docs/rendering.md, "Particles"): on or off over the show's
  // atmosphere.particles.enabled; none: as the show says.
  std::optional<bool> particles;
};

// cameraName "" = the show's first camera (or a default view of the stage when it has none).
// A fixture with a prism in becomes one beam per facet (docs/physics.md, "Prism").
Result<FrameState> buildFrame(const Show& show, const ProfileSet& profiles, const StageState& state,
                              const std::string& cameraName, const FrameOptions& options = {});
// The renderer's shadow-map cache key of a pose (equal keys promise equal poses).
uint64_t poseCacheKey(const BeamPose& pose);

CameraState cameraState(const CameraDef& def);
MediumState mediumState(const AtmosphereDef& def);
// The show's sun as the renderer sees it (off when absent or disabled).
SunState sunState(const std::optional<SunDef>& def);

}  // namespace haze
