// Effect waves (see effects.h). Random uses SplitMix64 on (seed, k, cycle) so that it needs no
// state and gives the same value for the same moment in any order of evaluation.
#include "shows/effects.h"

#include <cmath>
#include <cstdint>

namespace haze {

namespace {

constexpr double kTwoPi = 6.283185307179586;

std::uint64_t splitMix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

}  // namespace

const char* effectShapeName(EffectShape shape) {
  switch (shape) {
    case EffectShape::Sine: return "sine";
    case EffectShape::Circle: return "circle";
    case EffectShape::Square: return "square";
    case EffectShape::Ramp: return "ramp";
    case EffectShape::Random: break;
  }
  return "random";
}

double effectWave(const EffectDef& e, size_t k, size_t n, double t, double* tiltWave) {
  const double phaseDeg = e.phaseDeg + (n > 0 ? static_cast<double>(k) * e.spreadDeg / static_cast<double>(n) : 0.0);
  const double x = e.rateHz * t + phaseDeg / 360.0;
  const double cycle = std::floor(x), frac = x - cycle;
  if (tiltWave) *tiltWave = e.shape == EffectShape::Circle ? std::cos(kTwoPi * x) : 0.0;
  switch (e.shape) {
    case EffectShape::Sine:
    case EffectShape::Circle: return std::sin(kTwoPi * x);
    case EffectShape::Square: return frac < 0.5 ? 1.0 : -1.0;
    case EffectShape::Ramp: return 2.0 * frac - 1.0;
    case EffectShape::Random: break;
  }
  const std::uint64_t h = splitMix64(splitMix64(splitMix64(e.seed) ^ static_cast<std::uint64_t>(k)) ^
                                     static_cast<std::uint64_t>(static_cast<std::int64_t>(cycle)));
  return 2.0 * (static_cast<double>(h >> 11) * 0x1.0p-53) - 1.0;
}

}  // namespace haze
