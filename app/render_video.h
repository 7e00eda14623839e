// `haze render SHOW --video OUT`: a cue range played as on stage (shows/cue_timeline.h), one
// frame every 1/fps seconds, each rendered like a still of that moment at the session's quality
// and exposure, into a video file (renderer/output/video_writer.h) or an image sequence
// (OUT-%05d.png, OUT-%05d.exr: one file per frame, numbered from 0).
#pragma once

#include <filesystem>
#include <string>

#include "app/render_session.h"
#include "shows/cue_timeline.h"
#include "shows/show.h"
#include "shows/timecode.h"

namespace haze {

struct VideoJob {
  const CueList* list = nullptr;
  size_t from = 0, to = 0;  // cue indices, from <= to
  double holdS = 2.0;
  double durationS = 0.0;   // > 0: stop there (before or after the range's own end)
  int fps = 25;
  std::string codec = "libx264";
  std::filesystem::path out;
  bool progress = false;    // --progress: report even when stderr is not a terminal
  bool caption = false;     // burn "cue N label, t s" into video and PNG frames
  // --timeline FILE.json: the operator's GO times instead of from..to with holds.
  std::optional<CueTimeline> timeline;
  // Heads travel at the fixtures' speeds (docs/movement.md); false: --movement instant.
  bool realMovement = true;
  // --timecode START: timecode runs from START at timecodeRate frames per second and the list's
  // timecoded cues fire as `haze live --timecode` fires them (shows/dmx/live_playback.h); the
  // range and timeline are not used. The video ends holdS after the last timed cue's delay and
  // fade (or at durationS).
  std::optional<Timecode> timecodeStart;
  int timecodeRate = 25;
};

// {"go": [{"cue": "1", "at": 0}, {"cue": "2", "at": 8.5}, ...], "end": 30}: GO presses at
// increasing times (the first at 0 or later), follows still firing by themselves; "end"
// (optional) is where the video stops, by default holdS after the last GO's delay and fade.
// Errors name the file and the JSON pointer.
Result<CueTimeline> readTimeline(const std::filesystem::path& file, const Show& show, const CueList& list, double holdS);

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
