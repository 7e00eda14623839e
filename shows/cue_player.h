// CuePlayer: the clock-driven face of cue playback for the GUI and live playback. It is given the
// time (seconds on any monotonic clock) and never sleeps; ask for state(now) every frame.
//   GO       the next cue, fading from whatever is on stage now (mid-fade included) with the
//            next cue's timing (delay and fade, or its parts and fan); arms that cue's follow.
//   BACK     the previous cue with that cue's times (arms no follow).
//   GOTO N   from whatever is on stage now to cue N's tracked state with cue N's times; arms
//            cue N's follow.
//   follow   a cue with follow s makes the next cue GO by itself s seconds after its delay + fade
//            (its last part, cueDurationS) have finished. Follows fire at their exact times, however seldom the clock is read,
//            so a follow chain plays the same at 5 or 500 frames per second.
#pragma once

#include <optional>

#include "shows/playback.h"

namespace haze {

class CuePlayer {
 public:
  // The show, profiles and list must outlive the player. Before the first GO every fixture is at
  // its defaults and no cue is active.
  CuePlayer(const Show& show, const ProfileSet& profiles, const CueList& list);

  // Each returns false (and changes nothing) when there is no such cue.
  bool go(double nowS);
  bool back(double nowS);
  bool gotoCue(size_t cueIndex, double nowS);
  // Puts cue cueIndex's full state on stage at once, as if its fade had long finished, with no
  // follow armed (loading a show at a cue, or `haze state --follow`).
  bool jumpTo(size_t cueIndex, double nowS);

  // Fires the follows due by nowS, then returns the stage at nowS.
  StageState state(double nowS);
  // Fires the follows due by nowS.
  void update(double nowS);
  // The stage at nowS as it stands, firing no follow (for merging several lists in time order).
  StageState peek(double nowS) const { return stageAt(nowS); }

  std::optional<size_t> currentCue() const { return current_; }  // the cue last gone into
  bool fading(double nowS) const;                                   // delay or fade under way
  std::optional<double> nextFollowAtS() const { return followAtS_; }
  // The stage the fade under way started from (the snapshot taken at GO). Several lists played
  // at once (shows/playbacks.h) replace in it the attributes another list had on stage then, so
  // that a list taking an attribute over fades it from what the audience saw.
  StageState& fadeStart() { return from_; }

 private:
  void start(size_t cueIndex, double atS, bool armFollow);
  StageState stageAt(double nowS) const;

  const Show& show_;
  const ProfileSet& profiles_;
  const CueList& list_;
  StageState from_, to_;
  const Cue* fadingCue_ = nullptr;  // the cue whose timing and effects play; none: at to_
  double durationS_ = 0.0;
  double goAtS_ = 0.0;
  std::optional<size_t> current_;
  std::optional<double> followAtS_;
};

}  // namespace haze
