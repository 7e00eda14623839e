// `haze render SHOW --video OUT`: a cue list played as on stage (shows/frame/video_timeline.h), one
// frame every 1/fps seconds, each rendered like a still of that moment at the session's quality
// and exposure, into a video file (renderer/output/video_writer.h) or an image sequence
// (OUT-%05d.png, OUT-%05d.exr: one file per frame, numbered from 0).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "app/render_session.h"
#include "shows/frame/frame_sequence.h"
#include "shows/frame/video_timeline.h"
#include "shows/show.h"

namespace haze {

struct VideoJob {
  VideoPlan plan;  // what plays when (shows/frame/video_timeline.h)
  std::string codec = "libx264";
  std::filesystem::path out;
  bool progress = false;    // --progress: report even when stderr is not a terminal
  bool caption = false;     // burn "cue N label, t s" into video and PNG frames
  // --frames A-B: only these frames of the sequence, each exactly as the whole run draws it
  // (docs/output.md, "Rendering on a cluster"); none: every frame.
  std::optional<FrameRange> frames;
  // --resume: a frame whose file is already there and complete (renderer/output/frame_files.h)
  // is not drawn again.
  bool resume = false;
};

// Renders the job; errors are one line (file and reason) and leave no file under the video's
// name. Ctrl-C stops between frames and is reported as an error ("interrupted").
struct VideoStats {
  int frames = 0;   // of the range rendered (--frames), all of them without it
  int drawn = 0;    // the others repeat an unchanged stage (holds, delays) or were there (--resume)
  int skipped = 0;  // complete already (--resume)
};

Result<VideoStats> renderVideo(RenderSession& session, const Show& show, const ProfileSet& profiles, const VideoJob& job);

}  // namespace haze
