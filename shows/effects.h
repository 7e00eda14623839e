// Parametric effects (docs/show-format.md, "Effects"): the wave each shape draws, a pure function
// of the time since GO, so a still, `haze state --at` and a video frame show the same value.
#pragma once

#include <cstddef>

#include "shows/show.h"

namespace haze {

const char* effectShapeName(EffectShape shape);  // "sine", "circle", "square", "ramp", "random"

// The wave of the k-th of n fixtures (in the group's order) t seconds after GO, in -1..1, at
// x = rate * t + (phase + k * spread / n) / 360 cycles: sine sin(2 pi x), square +1 for the first
// half of each cycle and -1 for the second, ramp 2 frac(x) - 1, random a value fixed for each
// whole cycle by the seed, k and the cycle's number. A circle is sine on pan and cosine on tilt:
// `tiltWave` gets cos(2 pi x) (0 for the other shapes).
double effectWave(const EffectDef& effect, size_t k, size_t n, double t, double* tiltWave = nullptr);

}  // namespace haze
