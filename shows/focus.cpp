// Focus to point in closed form. In the mount frame (pivot at the origin, q = R^T (point -
// position)) the beam axis passes through q when q = Ry(pan) Rx(tilt) (L + s (0,-1,0)) for some
// s > 0, L the lens offset. Rotations keep lengths, so |q|^2 = Lx^2 + (Ly - s)^2 + Lz^2 gives s;
// the y row of that equation holds tilt alone (Ry keeps y), and pan then turns the xz part onto
// q's. No iteration is needed, and the lens offset turning with the head is exact, not
// approximated. When no answer lies inside the ranges, a grid search with a local refinement finds
// the reachable direction with the smallest angle to the point.
#include "shows/focus.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/geometric.hpp>

#include "fixtures/pose.h"

namespace haze {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kRangeSlackDeg = 1e-3;  // answers this close to a limit count as inside
constexpr double kReachedM = 1e-3;

glm::dmat3 rotY(double a) {  // right-handed about +Y; glm is column-major
  double c = std::cos(a), s = std::sin(a);
  return glm::dmat3(c, 0, -s, 0, 1, 0, s, 0, c);
}
glm::dmat3 rotX(double a) {
  double c = std::cos(a), s = std::sin(a);
  return glm::dmat3(1, 0, 0, 0, c, s, 0, -s, c);
}

struct Aim {
  glm::dvec3 lens;  // mount frame
  glm::dvec3 beam;
};

Aim aimAt(const glm::dvec3& lensOffset, double panDeg, double tiltDeg) {
  glm::dmat3 m = rotY(panDeg * kDeg) * rotX(tiltDeg * kDeg);
  return {m * lensOffset, m * glm::dvec3(0, -1, 0)};
}

// Distance from q to the beam axis ahead of the lens, and the angle between beam and lens->q.
void miss(const glm::dvec3& lensOffset, const glm::dvec3& q, double panDeg, double tiltDeg, double& missM,
          double& angleRad) {
  Aim a = aimAt(lensOffset, panDeg, tiltDeg);
  glm::dvec3 d = q - a.lens;
  double along = glm::dot(d, a.beam);
  double len = glm::length(d);
  missM = along > 0.0 ? glm::length(d - along * a.beam) : len;
  angleRad = len > 0.0 ? std::acos(std::clamp(along / len, -1.0, 1.0)) : 0.0;
}

std::string deg(float v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

bool inRange(const Range& r, double v) { return v >= r.min - kRangeSlackDeg && v <= r.max + kRangeSlackDeg; }

double clampTo(const Range& r, double v) { return std::clamp(v, static_cast<double>(r.min), static_cast<double>(r.max)); }

double distance2(double p, double t, const FocusRequest& r) {
  double dp = p - r.currentPanDeg, dt = t - r.currentTiltDeg;
  return dp * dp + dt * dt;
}

// Exact answers (pan, tilt) in degrees, all branches, not yet range-checked or shifted by 360.
std::vector<std::pair<double, double>> exactAnswers(const glm::dvec3& L, const glm::dvec3& q, double panHintDeg) {
  std::vector<std::pair<double, double>> out;
  double k = glm::dot(q, q) - L.x * L.x - L.z * L.z;
  if (k < 0.0) return out;
  for (double root : {std::sqrt(k), -std::sqrt(k)}) {
    double s = L.y + root;
    if (s <= 1e-9) continue;  // the point would lie behind or at the lens
    glm::dvec3 v(L.x, L.y - s, L.z);
    double rho = std::hypot(v.y, v.z);
    if (rho < 1e-12) continue;
    double c = q.y / rho;
    if (std::abs(c) > 1.0 + 1e-12) continue;  // within the offset's reach of the pan axis
    c = std::clamp(c, -1.0, 1.0);
    double phi = std::atan2(v.z, v.y);
    for (double sign : {1.0, -1.0}) {
      double t = sign * std::acos(c) - phi;
      glm::dvec3 w = rotX(t) * v;
      double horizontal = std::hypot(q.x, q.z);
      double p = horizontal < 1e-12 && std::hypot(w.x, w.z) < 1e-12 ? panHintDeg * kDeg
                                                                      : std::atan2(q.x, q.z) - std::atan2(w.x, w.z);
      out.emplace_back(std::remainder(p / kDeg, 360.0), std::remainder(t / kDeg, 360.0));
    }
  }
  return out;
}

// The reachable pan/tilt with the smallest angle to the point: a grid over the ranges (ties go
// to the one nearest the current pan/tilt), then a pattern search with shrinking steps.
void nearestReachable(const FocusRequest& r, const glm::dvec3& L, const glm::dvec3& q, double& panDeg, double& tiltDeg) {
  auto err = [&](double p, double t) {
    double m, a;
    miss(L, q, p, t, m, a);
    return a;
  };
  auto steps = [](const Range& range) {
    double span = std::max(0.0, static_cast<double>(range.max) - range.min);
    return std::min(720, static_cast<int>(std::ceil(span / 2.0))) ;
  };
  // The current pan and tilt join the grid so that ties (a point straight above a fixture that
  // cannot tilt that far) keep the head where it is.
  auto values = [&](const Range& range, double current) {
    int n = steps(range);
    std::vector<double> v;
    for (int i = 0; i <= n; ++i) v.push_back(n == 0 ? range.min : range.min + (range.max - range.min) * i / n);
    v.push_back(clampTo(range, current));
    return v;
  };
  double best = std::numeric_limits<double>::infinity(), bestDist = best;
  for (double p : values(r.panDeg, r.currentPanDeg))
    for (double t : values(r.tiltDeg, r.currentTiltDeg)) {
      double e = err(p, t), d = distance2(p, t, r);
      if (e < best - 1e-9 || (e <= best + 1e-9 && d < bestDist)) {
        best = std::min(best, e);
        bestDist = d;
        panDeg = p;
        tiltDeg = t;
      }
    }
  best = err(panDeg, tiltDeg);
  for (double step = 1.0; step > 1e-6; step *= 0.5) {
    bool moved = true;
    for (int guard = 0; moved && guard < 200; ++guard) {
      moved = false;
      for (auto [dp, dt] : {std::pair{step, 0.0}, {-step, 0.0}, {0.0, step}, {0.0, -step}}) {
        double p = clampTo(r.panDeg, panDeg + dp), t = clampTo(r.tiltDeg, tiltDeg + dt);
        double e = err(p, t);
        if (e < best - 1e-13) {
          best = e;
          panDeg = p;
          tiltDeg = t;
          moved = true;
        }
      }
    }
  }
}

}  // namespace

FocusResult focusOnPoint(const FocusRequest& r, const glm::vec3& pointM) {
  glm::dmat3 mount(mountingRotation(r.rotationDeg));
  glm::dvec3 q = glm::transpose(mount) * (glm::dvec3(pointM) - glm::dvec3(r.positionM));
  glm::dvec3 L(r.lensOffsetM);

  FocusResult out;
  std::vector<std::pair<double, double>> answers = exactAnswers(L, q, r.currentPanDeg);
  bool anyExact = false;
  double bestDist = std::numeric_limits<double>::infinity();
  for (auto [p0, t0] : answers) {
    double m, a;
    miss(L, q, p0, t0, m, a);
    if (!(m < kReachedM)) continue;  // a root that only solves the squared equation
    anyExact = true;
    for (int kp = -3; kp <= 3; ++kp)
      for (int kt = -1; kt <= 1; ++kt) {
        double p = p0 + 360.0 * kp, t = t0 + 360.0 * kt;
        if (!inRange(r.panDeg, p) || !inRange(r.tiltDeg, t)) continue;
        double d = distance2(p, t, r);
        if (d < bestDist) {
          bestDist = d;
          out.panDeg = static_cast<float>(clampTo(r.panDeg, p));
          out.tiltDeg = static_cast<float>(clampTo(r.tiltDeg, t));
          out.reached = true;
        }
      }
  }
  if (!out.reached) {
    double p = r.currentPanDeg, t = r.currentTiltDeg;
    nearestReachable(r, L, q, p, t);
    out.panDeg = static_cast<float>(p);
    out.tiltDeg = static_cast<float>(t);
    if (glm::length(q) < 1e-6)
      out.note = "the point is at the fixture itself; there is no direction to aim at";
    else if (anyExact)
      out.note = "the point needs pan/tilt outside the fixture's ranges (pan " + deg(r.panDeg.min) + ".." +
                 deg(r.panDeg.max) + ", tilt " + deg(r.tiltDeg.min) + ".." +
                 deg(r.tiltDeg.max) + "); aimed as near as the ranges allow";
    else
      out.note = "no pan/tilt puts the beam axis through the point (it is too close to the fixture for its lens "
                 "offset); aimed as near as possible";
  }
  double m, a;
  miss(L, q, out.panDeg, out.tiltDeg, m, a);
  out.missM = static_cast<float>(m);
  out.missAngleDeg = static_cast<float>(a / kDeg);
  return out;
}

FocusResult focusOnPoint(const FixtureDef& fixture, const Profile& profile, const glm::vec3& pointM, float currentPanDeg,
                         float currentTiltDeg) {
  FocusRequest r;
  r.positionM = fixture.position;
  r.rotationDeg = fixture.rotationDeg;
  r.lensOffsetM = profile.lensOffset;
  r.panDeg = profile.panDeg;
  r.tiltDeg = profile.tiltDeg;
  r.currentPanDeg = currentPanDeg;
  r.currentTiltDeg = currentTiltDeg;
  return focusOnPoint(r, pointM);
}

}  // namespace haze
