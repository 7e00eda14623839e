// The sun in the reference integrator (docs/physics.md, "The sun"): its in-scattering along an
// eye ray and its irradiance at a surface point, with exact shadow rays against the venue.
#pragma once

#include <glm/vec3.hpp>

#include "shows/scene/bvh.h"
#include "shows/scene/frame_state.h"

namespace haze {

// The sun's L_in along [0, depthM] of the ray e + t v (v unit): the integral over the ray's
// chord through the venue's bounding box of sigma_s(x) p V_sun T_sun c E times the eye's
// transmittance. Steps of at most maxStepM, shadow edges found by bisection.
glm::vec3 sunInScatter(const Bvh& bvh, const MediumState& medium, const SunState& sun, const glm::vec3& e,
                       const glm::vec3& v, float depthM, float maxStepM = 0.02f);

// c E max(0, dot(n, -d)) V_sun T_sun at a surface point: the irradiance that rho / pi turns into
// radiance. `lifted` is the point nudged off the surface (the start of the shadow ray), ng the
// geometric normal facing the eye; a sun behind the surface's plane adds nothing.
glm::vec3 sunIrradiance(const Bvh& bvh, const MediumState& medium, const SunState& sun, const glm::vec3& position,
                        const glm::vec3& lifted, const glm::vec3& ng, const glm::vec3& n);

}  // namespace haze
