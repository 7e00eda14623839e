// A cue list played as on stage and sampled every 1/fps seconds: what `haze render --video`
// draws, frame by frame, without drawing anything (docs/output.md, "Video"). Three ways to
// play: a cue range with holds (shows/cue_timeline.h), the operator's GO times read from a
// timeline file, or timecode running from a start that fires the list's timed cues as `haze
// live --timecode` does (the same LivePlayback). Heads travel at the fixtures' speeds unless
// the plan says instant. The hazers go with the same GOs as the fixtures.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "fixtures/core/result.h"
#include "shows/cue_player.h"
#include "shows/cue_timeline.h"
#include "shows/hazer_levels.h"
#include "shows/movement.h"
#include "shows/playback.h"
#include "shows/show.h"
#include "shows/timecode.h"
#include "shows/frame/live_playback.h"

namespace haze {

struct VideoPlan {
  const CueList* list = nullptr;
  size_t from = 0, to = 0;  // cue indices, from <= to
  double holdS = 2.0;
  double durationS = 0.0;   // > 0: stop there (before or after the range's own end)
  int fps = 25;
  // --timeline FILE.json: the operator's GO times instead of from..to with holds.
  std::optional<CueTimeline> timeline;
  // Heads travel at the fixtures' speeds (docs/movement.md); false: --movement instant.
  bool realMovement = true;
  // --timecode START: timecode runs from START at timecodeRate frames per second and the list's
  // timecoded cues fire; the range and timeline are not used. The video ends holdS after the
  // last timed cue's delay and fade (or at durationS).
  std::optional<Timecode> timecodeStart;
  int timecodeRate = 25;
};

// {"go": [{"cue": "1", "at": 0}, {"cue": "2", "at": 8.5}, ...], "end": 30}: GO presses at
// increasing times (the first at 0 or later), follows still firing by themselves; "end"
// (optional) is where the video stops, by default holdS after the last GO's delay and fade.
// Errors name the file and the JSON pointer.
Result<CueTimeline> readTimeline(const std::filesystem::path& file, const Show& show, const CueList& list, double holdS);

class VideoTimeline {
 public:
  struct Frame {
    int index = 0;
    double timeS = 0.0;
    StageState state;                // the stage as it really is then (heads travelling)
    std::optional<size_t> cue;       // the list's current cue, when one is
    std::optional<Timecode> timecode;  // under timecode: its reading at this frame
    std::string fired;               // timecode: what fired at this frame ("" when nothing)
  };

  // show, profiles and plan.list must outlive the timeline.
  VideoTimeline(const Show& show, const ProfileSet& profiles, const VideoPlan& plan);

  int frames() const { return frames_; }
  double endS() const { return endS_; }
  // The hazers' levels over the whole video, from the same GOs as the fixtures.
  const HazerSchedule& hazers() const { return hazers_; }

  // The frames in order, from 0 to frames() - 1: each call plays on to the next one. An error
  // when timecode passes 24:00:00:00 at that frame.
  Result<Frame> next();

 private:
  void scheduleHazers(const Show& show, const ProfileSet& profiles);
  std::optional<Timecode> timecodeAt(double timeS) const;

  VideoPlan plan_;
  CueTimeline gos_;
  size_t firstCue_ = 0;
  long startFrame_ = 0;  // timecode: the start in frames at timecodeRate
  double endS_ = 0.0;
  int frames_ = 1;
  HazerSchedule hazers_;
  std::optional<LivePlayback> live_;
  CuePlayer player_;
  MovementFollower heads_;
  size_t nextGo_ = 0;
  int nextFrame_ = 0;
};

}  // namespace haze
