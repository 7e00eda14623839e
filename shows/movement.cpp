// The movement follower (see movement.h): a rate- and acceleration-limited pursuit of the command,
// stepped at a fixed step so that the same command gives the same motion at any frame rate.
#include "shows/movement.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <optional>

namespace haze {

namespace {

// The largest speed from which steps of dt, each slower by a * dt, stop within e (e >= 0): the
// discrete braking curve, so that the stepped head neither overshoots nor stops short.
double brakingSpeed(double e, double a, double dt) {
  if (!(e > 0.0)) return 0.0;
  const double steps = 0.5 * (std::sqrt(1.0 + 8.0 * e / (a * dt * dt)) - 1.0);
  return steps * a * dt;
}

}  // namespace

void stepAxis(AxisMotion& m, double target, double targetVel, const AxisLimits& l, double dt,
              std::optional<double> finalValue) {
  if (!(dt > 0.0)) return;
  const double a = std::max<double>(l.acceleration, Movement::kMinAcceleration);
  const double vmax = std::max<double>(l.speed, Movement::kMinSpeed);
  const double e = target - m.pos;
  // Towards the target as fast as the head can still brake onto it, relative to the target's
  // motion: the gap at the start of the step closes by (v - targetVel) * dt.
  const double gap = e - targetVel * dt;
  double want = targetVel + std::copysign(brakingSpeed(std::fabs(gap), a, dt), gap);
  if (finalValue) {  // and never so fast that it cannot stop where the command will end
    const double ef = *finalValue - m.pos;
    const double cap = brakingSpeed(std::fabs(ef), a, dt);
    want = ef >= 0.0 ? std::min(want, cap) : std::max(want, -cap);
  }
  want = std::clamp(want, -vmax, vmax);
  const double v = m.vel + std::clamp(want - m.vel, -a * dt, a * dt);
  const double p = m.pos + v * dt;
  const double after = target - p;
  const bool crossed = e != 0.0 && after != 0.0 && std::signbit(after) != std::signbit(e);
  if (std::fabs(after) <= 1e-9 * std::max(1.0, std::fabs(target)) ||
      (crossed && std::fabs(m.vel - targetVel) <= a * dt)) {
    m.pos = target;
    m.vel = std::clamp(targetVel, -vmax, vmax);
    return;
  }
  m.pos = p;
  m.vel = v;
}

MovementFollower::MovementFollower(const Show& show, const ProfileSet& profiles)
    : show_(show), profiles_(profiles) {}

MovementFollower::Axes MovementFollower::axesOf(int id, const Attributes& a, const Profile** profile) const {
  *profile = nullptr;
  if (const FixtureDef* f = show_.findFixture(id))
    if (auto p = profiles_.find(f->profile); p != profiles_.end() && p->second) *profile = p->second.get();
  Axes x;
  x.pan = a.panDeg;
  x.tilt = a.tiltDeg;
  x.zoom = a.zoomDeg.value_or(*profile ? (*profile)->fieldAngleDeg : 0.0f);
  // A head cannot travel past its ranges (which also bounds the simulation of a command far
  // outside them: at most range / the slowest speed).
  if (const Profile* p = *profile) {
    const auto within = [](double v, const Range& r) { return std::clamp<double>(v, std::min(r.min, r.max), std::max(r.min, r.max)); };
    x.pan = within(x.pan, p->panDeg);
    x.tilt = within(x.tilt, p->tiltDeg);
    x.zoom = within(x.zoom, p->zoomDeg);
  }
  return x;
}

void MovementFollower::reset(const StageState& state, double nowS) {
  heads_.clear();
  nowS_ = nowS;
  for (const auto& [id, a] : state) {
    Head h;
    h.command = axesOf(id, a, &h.profile);
    h.pan.pos = h.command.pan;
    h.tilt.pos = h.command.tilt;
    h.zoom.pos = h.command.zoom;
    heads_[id] = h;
  }
}

bool MovementFollower::settled() const {
  for (const auto& [id, h] : heads_) {
    if (h.pan.pos != h.command.pan || h.tilt.pos != h.command.tilt || h.zoom.pos != h.command.zoom) return false;
    if (h.pan.vel != 0.0 || h.tilt.vel != 0.0 || h.zoom.vel != 0.0) return false;
  }
  return true;
}

StageState MovementFollower::advance(const StageState& commanded, double nowS, bool interpolate,
                                     const StageState* finalState) {
  const double span = nowS - nowS_;
  const long steps = span > 0.0 ? std::max(1L, std::lround(std::ceil(span / kStepS - 1e-9))) : 0;
  for (const auto& [id, a] : commanded) {
    const Profile* profile = nullptr;
    const Axes to = axesOf(id, a, &profile);
    auto it = heads_.find(id);
    if (it == heads_.end() || it->second.profile != profile) {
      Head h;
      h.command = to;
      h.profile = profile;
      h.pan.pos = to.pan;
      h.tilt.pos = to.tilt;
      h.zoom.pos = to.zoom;
      heads_[id] = h;
      continue;
    }
    Head& h = it->second;
    const Axes from = h.command;
    const Movement limits = profile ? profile->movement : Movement{};
    const double dt = steps > 0 ? span / static_cast<double>(steps) : 0.0;
    std::optional<Axes> last;
    if (finalState)
      if (auto fin = finalState->find(id); fin != finalState->end()) {
        const Profile* ignored = nullptr;
        last = axesOf(id, fin->second, &ignored);
      }
    const auto endOf = [&](double Axes::*axis) { return last ? std::optional<double>((*last).*axis) : std::nullopt; };
    for (long k = 1; k <= steps; ++k) {
      const double f = interpolate ? static_cast<double>(k) / static_cast<double>(steps) : 1.0;
      const double rate = interpolate && span > 0.0 ? 1.0 / span : 0.0;
      stepAxis(h.pan, from.pan + (to.pan - from.pan) * f, (to.pan - from.pan) * rate, limits.pan, dt, endOf(&Axes::pan));
      stepAxis(h.tilt, from.tilt + (to.tilt - from.tilt) * f, (to.tilt - from.tilt) * rate, limits.tilt, dt,
               endOf(&Axes::tilt));
      stepAxis(h.zoom, from.zoom + (to.zoom - from.zoom) * f, (to.zoom - from.zoom) * rate, limits.zoom, dt,
               endOf(&Axes::zoom));
    }
    h.command = to;
  }
  for (auto it = heads_.begin(); it != heads_.end();) {
    it = commanded.count(it->first) ? std::next(it) : heads_.erase(it);
  }
  nowS_ = std::max(nowS_, nowS);
  return apply(commanded);
}

StageState MovementFollower::apply(const StageState& commanded) const {
  StageState out = commanded;
  for (auto& [id, a] : out) {
    auto it = heads_.find(id);
    if (it == heads_.end()) continue;
    const Head& h = it->second;
    if (h.pan.pos != h.command.pan) a.panDeg = static_cast<float>(h.pan.pos);
    if (h.tilt.pos != h.command.tilt) a.tiltDeg = static_cast<float>(h.tilt.pos);
    if (h.zoom.pos != h.command.zoom) a.zoomDeg = static_cast<float>(h.zoom.pos);
  }
  return out;
}

StageState movingStateAt(const Show& show, const ProfileSet& profiles, const CueList& list, size_t cueIndex,
                         double secondsSinceGo) {
  assert(cueIndex < list.cues.size() && "movingStateAt: cue index past the end of the list; use findCue");
  const StageState from = cueIndex == 0 ? defaultState(show) : trackedState(show, profiles, list, cueIndex - 1);
  const StageState to = trackedState(show, profiles, list, cueIndex);
  const Cue& cue = list.cues[cueIndex];
  const double doneS = cueDurationS(show, cue);
  return followCommand(
      show, profiles, [&](double t) { return blendStatesAt(show, profiles, from, to, cue, t); },
      [&](double t) { return t >= doneS; }, secondsSinceGo, &to);
}

}  // namespace haze
