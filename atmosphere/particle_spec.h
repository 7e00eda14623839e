// What a show says about visible dust in its beams (docs/shows.md, "Particles"): plain data,
// read and written by shows/, turned into particles by shows/scene/particles.h.
#pragma once

#include <cstdint>

namespace haze {

struct ParticleSettings {
  bool enabled = false;
  float densityPerM3 = 50.0f;   // particles per m^3 where D = 1 (number density n0 D(x))
  float sizeUm = 40.0f;         // median diameter of the log-normal size distribution
  float sizeSigma = 0.5f;       // standard deviation of ln(diameter)
  // Display gain over the particle's physical scattering (docs/physics.md, "Particles"): real
  // dust at stage distances is far below a pixel and far fainter than the haze it floats in.
  float brightness = 2000.0f;
  uint32_t seed = 1;
  bool operator==(const ParticleSettings&) const = default;
};

inline constexpr float kMaxParticleDensityPerM3 = 5000.0f;

}  // namespace haze
