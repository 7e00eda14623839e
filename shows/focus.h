// Focus to point: the pan and tilt that aim a fixture's beam axis through a point in the world,
// for clicking a spot on stage in the GUI (docs/physics.md, "Mounting, pan and tilt").
#pragma once

#include <string>

#include <glm/vec3.hpp>

#include "fixtures/profile.h"
#include "shows/show.h"

namespace haze {

struct FocusRequest {
  glm::vec3 positionM{0.0f};
  glm::vec3 rotationDeg{0.0f};    // mounting, R = Rz * Ry * Rx
  glm::vec3 lensOffsetM{0.0f};    // head frame, turns with pan and tilt
  Range panDeg{-270.0f, 270.0f};
  Range tiltDeg{-135.0f, 135.0f};
  float currentPanDeg = 0.0f;     // among equivalent answers, the one nearest this wins
  float currentTiltDeg = 0.0f;
};

struct FocusResult {
  float panDeg = 0.0f;
  float tiltDeg = 0.0f;
  // True when the beam axis passes through the point (within 1 mm); false when the point is out
  // of reach and pan/tilt give the nearest reachable direction instead.
  bool reached = false;
  float missM = 0.0f;        // distance from the point to the beam axis (ahead of the lens)
  float missAngleDeg = 0.0f; // angle between the beam and the direction from the lens to the point
  std::string note;          // why the point is out of reach ("" when reached)
};

// Solves in closed form (see focus.cpp): the head must turn the vector lensOffset + s * (0,-1,0),
// whose length is known once s is, onto the point as seen from the mount; tilt then pan follow
// from one equation each. Among pan +/- 360 and the flipped pair (pan + 180, -tilt) it keeps the
// answer inside the ranges nearest the current pan/tilt. Out of reach (limits, the point within
// the lens offset's reach of the pan axis, or at the fixture) it searches the ranges for the
// direction nearest the point.
FocusResult focusOnPoint(const FocusRequest& request, const glm::vec3& pointM);
// The same for a fixture of a show and its profile.
FocusResult focusOnPoint(const FixtureDef& fixture, const Profile& profile, const glm::vec3& pointM,
                         float currentPanDeg, float currentTiltDeg);

}  // namespace haze
