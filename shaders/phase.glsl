// Phase functions of docs/physics.md, normalised over the sphere; cosA = dot(w_in, w_out).
#include "interface.h"

layout(location = HAZE_LOC_PHASE) uniform int uPhase;  // HAZE_PHASE_*
layout(location = HAZE_LOC_PHASE_G) uniform float uG;

// STATIC_FEATURES programs have the frame's phase function compiled in (PHASE_KIND, one of
// HAZE_PHASE_*), the others read it from uPhase.
#ifndef PHASE_KIND
#define PHASE_KIND uPhase
#endif

float phaseFunction(float cosA) {
  const float PI_ = 3.14159265358979323846;
  if (PHASE_KIND == HAZE_PHASE_ISOTROPIC) return 1.0 / (4.0 * PI_);
  if (PHASE_KIND == HAZE_PHASE_HENYEY_GREENSTEIN) {
    float d = 1.0 + uG * uG - 2.0 * uG * cosA;
    return (1.0 - uG * uG) / (4.0 * PI_ * d * sqrt(d));
  }
  float c2 = 0.5 * (1.0 + cosA);  // cos^2(a/2)
  return (1.0 + 9.0 * c2 * c2 * c2) / (13.0 * PI_);
}
