// CuePlayer (see cue_player.h): one crossfade at a time, from a snapshot of the stage at the
// moment of GO to the target cue's tracked state; follows are kept as the absolute time at
// which they fire.
#include "shows/cue_player.h"

namespace haze {

CuePlayer::CuePlayer(const Show& show, const ProfileSet& profiles, const CueList& list)
    : show_(show), profiles_(profiles), list_(list), from_(defaultState(show)), to_(from_) {}

StageState CuePlayer::stageAt(double nowS) const {
  if (!fadingCue_) return to_;
  return blendStatesAt(show_, profiles_, from_, to_, *fadingCue_, nowS - goAtS_);
}

void CuePlayer::start(size_t cueIndex, double atS, bool armFollow) {
  const Cue& cue = list_.cues[cueIndex];
  from_ = stageAt(atS);
  to_ = trackedState(show_, profiles_, list_, cueIndex);
  fadingCue_ = &cue;
  durationS_ = cueDurationS(show_, cue);
  goAtS_ = atS;
  current_ = cueIndex;
  followAtS_.reset();
  if (armFollow && cue.followS && cueIndex + 1 < list_.cues.size())
    followAtS_ = atS + durationS_ + *cue.followS;
}

void CuePlayer::update(double nowS) {
  // Each firing moves one cue on and a chain stops at the last cue, so this ends.
  while (followAtS_ && *followAtS_ <= nowS) {
    double at = *followAtS_;
    followAtS_.reset();
    go(at);
  }
}

StageState CuePlayer::state(double nowS) {
  update(nowS);
  return stageAt(nowS);
}

bool CuePlayer::go(double nowS) {
  update(nowS);
  size_t next = current_ ? *current_ + 1 : 0;
  if (next >= list_.cues.size()) return false;
  start(next, nowS, true);
  return true;
}

bool CuePlayer::back(double nowS) {
  update(nowS);
  if (!current_ || *current_ == 0) return false;
  start(*current_ - 1, nowS, false);
  return true;
}

bool CuePlayer::gotoCue(size_t cueIndex, double nowS) {
  update(nowS);
  if (cueIndex >= list_.cues.size()) return false;
  start(cueIndex, nowS, true);
  return true;
}

bool CuePlayer::jumpTo(size_t cueIndex, double nowS) {
  if (cueIndex >= list_.cues.size()) return false;
  from_ = to_ = trackedState(show_, profiles_, list_, cueIndex);
  // As if GO had been long enough ago for the fade to be over; its effects run on.
  // from_ == to_, so only the effects move; fading() is false from now on.
  fadingCue_ = &list_.cues[cueIndex];
  goAtS_ = nowS - cueDurationS(show_, *fadingCue_);
  durationS_ = 0.0;
  current_ = cueIndex;
  followAtS_.reset();
  return true;
}

bool CuePlayer::fading(double nowS) const {
  return current_ && nowS - goAtS_ < durationS_;
}

}  // namespace haze
