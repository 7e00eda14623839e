// `haze render SHOW --video OUT`: a cue list played as on stage (shows/frame/video_timeline.h), one
// frame every 1/fps seconds, each rendered like a still of that moment at the session's quality
// and exposure, into a video file (renderer/output/video_writer.h) or an image sequence
// (OUT-%05d.png, OUT-%05d.exr: one file per frame, numbered from 0).
#pragma once

#include <filesystem>
#include <string>

#include "app/render_session.h"
#include "shows/frame/video_timeline.h"
#include "shows/show.h"

namespace haze {

struct VideoJob {
  VideoPlan plan;  // what plays when (shows/frame/video_timeline.h)
  std::string codec = "libx264";
  std::filesystem::path out;
  bool progress = false;    // --progress: report even when stderr is not a terminal
  bool caption = false;     // burn "cue N label, t s" into video and PNG frames
};

// True when `out` names an image sequence: a printf-style frame number (%d, %05d) and .png or
// .exr. A '%' that is not one such number is an error (named in `error`).
bool isImageSequence(const std::filesystem::path& out, std::string& error);

// Renders the job; errors are one line (file and reason) and leave no file under the video's
// name. Ctrl-C stops between frames and is reported as an error ("interrupted").
struct VideoStats {
  int frames = 0;
  int drawn = 0;  // the others repeat an unchanged stage (holds, delays)
};

Result<VideoStats> renderVideo(RenderSession& session, const Show& show, const ProfileSet& profiles, const VideoJob& job);

}  // namespace haze
