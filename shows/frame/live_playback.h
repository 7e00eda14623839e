// The cue engine of `haze live` when it is remote-controlled (OSC) or on timecode: every cue list
// of the show on one Playbacks (shows/playbacks.h; /haze/go, /haze/back, /haze/cue and timecode
// play the chosen list, /haze/list/NAME/... any list), a programmer that OSC fixture messages
// set, and the DMX input laid over both for the fixtures on universes a console is sending. Time is passed in (seconds on a monotonic
// clock), so tests inject it.
//
// Timecode (docs/live.md, "Timecode"): cues with a `timecode` fire when the time reaches it.
// Running forward (each reading 0..1 s after the previous one) every cue passed since the last
// reading fires, in list order, with its own delay and fade. Anything else is a jump (backwards,
// ahead by more than a second, or the first reading): the stage chases to the last cue at or
// before the new time at once, its fade finished, the way consoles chase on a timecode jump;
// before the first timed cue the stage goes back to its defaults.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "shows/playbacks.h"
#include "shows/remote_command.h"
#include "shows/timecode.h"

namespace haze {

class LivePlayback {
 public:
  // show, profiles and list must outlive the playback; list may be null (a show without cues:
  // GO, BACK and GOTO then answer that there is nothing to play).
  LivePlayback(const Show& show, const ProfileSet& profiles, const CueList* list);

  // An OSC command. The result says what happened ("cue 3") or why nothing did.
  Result<std::string> apply(const RemoteCommand& command, double nowS);
  // A timecode reading at fps frames per second; returns what it fired ("" when nothing).
  std::string timecode(const Timecode& time, double fps, double nowS);

  // Playback at nowS, the fixtures in dmxFixtures taken from dmx instead, the programmer over all.
  StageState stage(double nowS, const StageState& dmx, const std::set<int>& dmxFixtures);

  std::optional<size_t> currentCue() const { return list_ ? playbacks_.currentCue(main_) : std::nullopt; }
  const std::map<int, CueValues>& programmer() const { return programmer_; }
  // The camera /haze/camera chose ("" until then: the command line's).
  const std::string& camera() const { return camera_; }

 private:
  std::string chase(const Timecode& time, double nowS);

  const Show& show_;
  const CueList* list_;
  Playbacks playbacks_;
  size_t main_ = 0;  // list_'s playback
  std::map<int, CueValues> programmer_;
  std::string camera_;
  std::vector<std::pair<Timecode, size_t>> timed_;  // the list's timed cues, in list order
  std::optional<Timecode> lastTime_;
  double lastSeconds_ = 0.0;
};

}  // namespace haze
