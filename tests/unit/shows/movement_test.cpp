// Movement at the fixture's speed (shows/movement.h) against the closed form of a trapezoidal
// velocity profile: a head starting at rest, accelerating at a to top speed v, cruising, and
// braking at a onto the target (docs/movement.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "shows/movement.h"

namespace haze {
namespace {

// Distance covered t seconds into a rest-to-rest move of d (> 0) at top speed v, acceleration a.
double trapezoid(double d, double v, double a, double t) {
  double ramp = v / a, total = d / v + v / a;
  if (d < v * v / a) {  // never reaches top speed: a triangle
    ramp = std::sqrt(d / a);
    total = 2.0 * ramp;
    v = a * ramp;
  }
  if (t <= 0.0) return 0.0;
  if (t >= total) return d;
  if (t < ramp) return 0.5 * a * t * t;
  if (t > total - ramp) return d - 0.5 * a * (total - t) * (total - t);
  return 0.5 * a * ramp * ramp + v * (t - ramp);
}

double arrivalTime(double d, double v, double a) {
  return d < v * v / a ? 2.0 * std::sqrt(d / a) : d / v + v / a;
}

// The step response of stepAxis follows the trapezoid within a few steps' travel at top speed.
TEST(Movement, StepResponseIsTheTrapezoid) {
  for (auto [d, v, a] : {std::tuple{180.0, 270.0, 1080.0}, std::tuple{10.0, 270.0, 1080.0},
                         std::tuple{540.0, 100.0, 50.0}, std::tuple{30.0, 40.0, 1e6}}) {
    const AxisLimits l{static_cast<float>(v), static_cast<float>(a), MovementSource::Native};
    AxisMotion m;
    const double dt = MovementFollower::kStepS;
    double worst = 0.0, arrived = -1.0;
    for (int k = 1; k <= 2000000 && arrived < 0.0; ++k) {
      stepAxis(m, d, 0.0, l, dt);
      const double t = k * dt;
      worst = std::max(worst, std::fabs(m.pos - trapezoid(d, v, a, t)));
      EXPECT_LE(std::fabs(m.vel), v + 1e-9);
      if (m.pos == d && m.vel == 0.0) arrived = t;
    }
    // Measured: the discrete braking curve stays within half a step of travel at top speed of
    // the closed form and arrives within one step of it; margins of 2x.
    EXPECT_LE(worst, v * dt) << "d " << d << " v " << v << " a " << a;
    EXPECT_NEAR(arrived, arrivalTime(d, v, a), 2.0 * dt) << "d " << d << " v " << v << " a " << a;
  }
}

// A command slower than the head is followed: the head ends on it without passing it by more than
// a step's slack (it brakes for where the fade ends), and changes speed no faster than its
// acceleration allows.
TEST(Movement, SlowRampIsTrackedWithinTheLimits) {
  const AxisLimits l{270.0f, 1080.0f, MovementSource::Native};
  AxisMotion m;
  const double dt = MovementFollower::kStepS, r = 90.0;  // the command: 90 deg/s for 1 s
  double lastVel = 0.0;
  for (int k = 1; k <= 3000; ++k) {
    const double t = k * dt;
    const double target = std::min(t, 1.0) * r, vel = t < 1.0 ? r : 0.0;
    stepAxis(m, target, vel, l, dt, 90.0);
    EXPECT_LE(std::fabs(m.vel - lastVel), l.acceleration * dt + 1e-6) << t;
    // The discrete braking curve's slack: at most a * dt^2 past (measured 1e-4 degrees).
    EXPECT_LE(m.pos, target + l.acceleration * dt * dt) << t;
    EXPECT_LE(std::fabs(m.vel), l.speed + 1e-9) << t;
    lastVel = m.vel;
  }
  EXPECT_EQ(m.pos, 90.0);
  EXPECT_EQ(m.vel, 0.0);
}

struct OneFixture {
  Show show;
  ProfileSet profiles;
  CueList list;
  OneFixture(float speed, float accel) {
    auto p = std::make_shared<Profile>();
    p->name = "mover";
    p->movement.pan = {speed, accel, MovementSource::Native};
    profiles["mover"] = p;
    FixtureDef f;
    f.id = 1;
    f.profile = "mover";
    show.fixtures.push_back(f);
    Cue c1, c2;
    c1.number = "1";
    c1.values[1].panDeg = 0.0f;
    c1.values[1].intensity = 1.0f;
    c2.number = "2";
    c2.fadeS = 0.2;
    c2.values[1].panDeg = 180.0f;
    list.name = "Main";
    list.cues = {c1, c2};
  }
};

// 180 degrees of pan asked in 0.2 s of a fixture that does 540 degrees in 2 s
// arrives when its speed lets it (at 270 deg/s with a 0.25 s ramp: 180/270 + 0.25 s), not at 0.2 s.
TEST(Movement, CueFadeArrivesAtTheFixturesSpeed) {
  OneFixture s(270.0f, 1080.0f);
  const double expect = arrivalTime(180.0, 270.0, 1080.0);
  const double frame = 1.0 / 30.0;
  EXPECT_LT(movingStateAt(s.show, s.profiles, s.list, 1, expect - frame).at(1).panDeg, 179.9f);
  EXPECT_FLOAT_EQ(movingStateAt(s.show, s.profiles, s.list, 1, expect + frame).at(1).panDeg, 180.0f);
  EXPECT_FLOAT_EQ(movingStateAt(s.show, s.profiles, s.list, 1, 1e9).at(1).panDeg, 180.0f);
  // Instant playback is the fade itself.
  EXPECT_FLOAT_EQ(stateAt(s.show, s.profiles, s.list, 1, 0.2).at(1).panDeg, 180.0f);
  // Attributes other than pan, tilt and zoom are not delayed.
  EXPECT_FLOAT_EQ(movingStateAt(s.show, s.profiles, s.list, 1, 0.1).at(1).intensity, 1.0f);
}

// A full state (no --at) of a cue whose effect keeps moving the pan: the heads follow it without
// ever settling, and the walk still ends (it used to step 1 ms at a time towards 1e9 s).
TEST(Movement, AFullStateUnderARunningEffectEnds) {
  OneFixture s(270.0f, 1080.0f);
  const auto swinging = [](double t) {
    StageState st;
    st[1].panDeg = static_cast<float>(30.0 * std::sin(t));
    st[1].intensity = 1.0f;
    return st;
  };
  const StageState out = followCommand(s.show, s.profiles, swinging, [](double) { return true; }, 1e9);
  ASSERT_TRUE(out.count(1));
  EXPECT_LE(std::abs(out.at(1).panDeg), 30.5f);
}

// A DMX jump followed by advancing at irregular moments (as polls return) lands where fine
// steps do: the motion does not depend on the frame rate.
TEST(Movement, FollowerIsFrameRateIndependent) {
  OneFixture s(270.0f, 1080.0f);
  StageState rest = trackedState(s.show, s.profiles, s.list, 0);
  StageState jump = trackedState(s.show, s.profiles, s.list, 1);
  MovementFollower fine(s.show, s.profiles), coarse(s.show, s.profiles);
  fine.reset(rest, 0.0);
  coarse.reset(rest, 0.0);
  double t = 0.0;
  for (double dt : {0.0167, 0.1, 0.0031, 0.05, 0.2, 0.0167, 0.09}) {
    t += dt;
    const float c = coarse.advance(jump, t, false).at(1).panDeg;
    float f = 0.0f;
    for (double u = std::max(0.0, t - dt); u < t - 1e-12;) {
      u = std::min(t, u + MovementFollower::kStepS);
      f = fine.advance(jump, u, false).at(1).panDeg;
    }
    EXPECT_NEAR(c, f, 0.05f) << t;
    EXPECT_NEAR(c, trapezoid(180.0, 270.0, 1080.0, t), 270.0 * MovementFollower::kStepS) << t;
  }
}

}  // namespace
}  // namespace haze
