// Where an eye ray is inside a beam's cone: I_eff is exactly 0 outside the cone of half-angle
// BeamOptics::cutoffHalfAngleRad() around z_b, so the reference marches only this interval.
// Exact (in double precision), including a camera inside the cone, the back cone of the
// quadric (which is dark) and rays grazing the cone's surface.
#pragma once

#include <glm/vec3.hpp>

namespace haze {

struct ConeInterval {
  double t0 = 0.0;
  double t1 = 0.0;
  bool empty() const { return !(t1 > t0); }
};

// The part of [tMin, tMax] where x(t) = origin + t * dir (dir unit) satisfies
// dot(x - apex, axis) >= |x - apex| cos(halfAngleRad), for 0 < halfAngleRad < pi / 2 (the cone
// is convex, so the set is one interval). axis is unit.
ConeInterval intersectCone(const glm::vec3& origin, const glm::vec3& dir, const glm::vec3& apex,
                           const glm::vec3& axis, float halfAngleRad, double tMin, double tMax);

}  // namespace haze
