// Movement at the fixture's own speed (docs/movement.md): pan, tilt and zoom follow the commanded
// value (a cue's fade, a DMX value, the programmer) within the profile's top speed and
// acceleration. One follower, stepped at a fixed kStepS, serves cue playback (simulated from GO,
// so `haze state --at` and renders of a fade are deterministic), `haze live` and the GUI.
#pragma once

#include <algorithm>
#include <map>
#include <optional>

#include "fixtures/movement.h"
#include "shows/playback.h"

namespace haze {

// How attributes reach the stage: at the fixture's speed (the default), or at once (the
// commanded value itself, as before movement was modelled).
enum class MovementMode { Real, Instant };

struct AxisMotion {
  double pos = 0.0;
  double vel = 0.0;
};

// One step of dt seconds towards `target` (its value at the end of the step), which itself moves
// at targetVel: change speed by at most l.acceleration * dt, never faster than l.speed, and
// brake along the discrete braking curve so as to arrive without overshoot; with finalValue
// (where a fade will end), never so fast that the head could not stop there. A head that
// reaches or crosses the target within one step's change of speed is put on it.
void stepAxis(AxisMotion& m, double target, double targetVel, const AxisLimits& l, double dt,
              std::optional<double> finalValue = std::nullopt);

class MovementFollower {
 public:
  static constexpr double kStepS = 0.001;

  // The show and profiles must outlive the follower.
  MovementFollower(const Show& show, const ProfileSet& profiles);

  // Every fixture at rest on `state` at time nowS.
  void reset(const StageState& state, double nowS);
  // Advances the heads to nowS in kStepS steps. The command moves linearly from the last one
  // given to `commanded` across the interval when `interpolate` (a sampled fade: the GUI), else
  // it is `commanded` throughout (a DMX jump is a step). Fixtures seen for the first time start
  // at rest on their commanded value. finalState: where the command ends (a fade's target), so
  // the heads brake for it. Returns the stage as it really is at nowS.
  StageState advance(const StageState& commanded, double nowS, bool interpolate,
                     const StageState* finalState = nullptr);
  // True when every head is at rest on the command last given.
  bool settled() const;

  // One fixture's commanded pan, tilt and zoom (an unset zoom is the profile's field angle).
  struct Axes {
    double pan = 0.0, tilt = 0.0, zoom = 0.0;
  };

 private:
  struct Head {
    AxisMotion pan, tilt, zoom;
    Axes command;
    const Profile* profile = nullptr;
  };
  Axes axesOf(int id, const Attributes& a, const Profile** profile) const;
  StageState apply(const StageState& commanded) const;

  const Show& show_;
  const ProfileSet& profiles_;
  std::map<int, Head> heads_;
  double nowS_ = 0.0;
};

// The stage secondsSinceGo after GO into cue cueIndex with every head starting at rest on the
// cue before (playback.h stateAt, followed at the fixtures' speeds).
StageState movingStateAt(const Show& show, const ProfileSet& profiles, const CueList& list, size_t cueIndex,
                         double secondsSinceGo);

// No head takes this long to arrive: past it, a command that is steady but for an effect (which
// heads follow without ever settling) is as it will stay.
inline constexpr double kMaxArrivalS = 60.0;

// Samples commandAt(t) every kStepS from t = 0 (heads at rest on commandAt(0)) to atS and
// returns the real stage at atS. Stops early once the command has stopped changing for good
// (steady(t): no fade or follow after t) and every head has arrived, or kMaxArrivalS after that
// when an effect keeps the heads moving (so a full state, atS = 1e9, ends). finalState as in
// MovementFollower::advance.
template <class CommandAt, class Steady>
StageState followCommand(const Show& show, const ProfileSet& profiles, CommandAt&& commandAt, Steady&& steady,
                         double atS, const StageState* finalState = nullptr) {
  MovementFollower f(show, profiles);
  StageState cmd = commandAt(0.0);
  f.reset(cmd, 0.0);
  StageState out = cmd;
  double steadySinceS = -1.0;
  for (long k = 1;; ++k) {
    const double t = std::min(atS, static_cast<double>(k) * MovementFollower::kStepS);
    cmd = commandAt(t);
    out = f.advance(cmd, t, true, finalState);
    if (t >= atS) return out;
    if (!steady(t)) continue;
    if (f.settled()) return cmd;
    if (steadySinceS < 0.0) steadySinceS = t;
    else if (t - steadySinceS > kMaxArrivalS) return out;
  }
}

}  // namespace haze
