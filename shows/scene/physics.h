// docs/physics.md's formulas as CPU functions, shared by the reference integrator, tests and the
// frame builder. shaders/physics.glsl holds their GLSL twins; tests/render compares the two.
#pragma once

#include <glm/vec3.hpp>

#include "shows/scene/frame_state.h"

namespace haze {

constexpr float kPi = 3.14159265358979323846f;

// Phase function p(a) [1/sr], integral over the sphere = 1; cosA = dot(w_in, w_out).
float phaseFunction(const MediumState& m, float cosA);

// I_eff towards world point x from a beam, in cd per RGB channel, without visibility.
glm::vec3 beamIntensityTowards(const BeamState& beam, const glm::vec3& x);

// The way the sun's light travels, for a sun at azimuthDeg (from north, -Z, towards east, +X,
// seen from above) and elevationDeg above the horizon: minus the unit vector towards the sun,
// (sin az cos el, sin el, -cos az cos el).
glm::vec3 sunDirection(float azimuthDeg, float elevationDeg);

// The length of the ray from x towards the sun (-direction, unit) inside the box [lo, hi]: the
// sun's path through the medium (docs/physics.md, "The sun"). 0 from a point outside the box.
float sunPathInBox(const glm::vec3& x, const glm::vec3& direction, const glm::vec3& lo, const glm::vec3& hi);

}  // namespace haze
