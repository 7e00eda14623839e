// Visible dust in the beams (docs/rendering.md, "Particles"; docs/physics.md, "Particles"): a
// display option that draws single particles where beams light them. This is the CPU half,
// plain data and no GL: where the particles are at a time, and how large. Particles are points
// of a world lattice of cells, each cell's count and positions a hash of its integer
// coordinates and the seed, so a seed gives the same dust at the same time on every render;
// the lattice drifts with the room's air and settles under gravity, each particle wobbling
// about its drifting place as a function of the show time.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "atmosphere/density_field.h"
#include "atmosphere/particle_spec.h"

namespace haze {


inline constexpr float kParticleCellM = 0.25f;        // the lattice's cell
inline constexpr float kParticleWobbleM = 0.03f;      // amplitude of each particle's own motion
inline constexpr size_t kDefaultParticleLimit = 200000;  // sprites per frame (see ParticleSet::wanted)

// Where the particles are: the settings, the show time and the room's air.
struct ParticleState {
  ParticleSettings settings;
  double timeS = 0.0;
  glm::vec3 airFlowMps{0.0f};
  size_t limit = kDefaultParticleLimit;
};

// A beam's cone as far as it lights anything (its reach), the particles' search region.
struct ParticleCone {
  glm::vec3 apex{0.0f};
  glm::vec3 axis{0.0f, -1.0f, 0.0f};  // unit
  float halfAngleRad = 0.2f;
  float lengthM = 10.0f;
  int beam = 0;  // what Particle::beam holds for the particles found in it
};

struct Particle {
  glm::vec3 positionM{0.0f};
  float crossSectionM2 = 0.0f;  // geometric: pi d^2 / 4
  int beam = 0;                 // the cone it was found in (a particle in two cones is listed twice)
};

struct ParticleSet {
  std::vector<Particle> particles;
  size_t wanted = 0;  // before the limit; particles.size() < wanted means some were left out
  size_t cellsTried = 0;
};

// The common drift of the dust: the room's air plus the settling speed of the median particle
// (Stokes' law for a sphere of density 1000 kg/m^3 in air).
glm::vec3 particleDrift(const ParticleSettings& settings, const glm::vec3& airFlowMps);
float settlingSpeedMps(float diameterUm);

// The particles inside the cones at the state's time, within [boundsMin, boundsMax] (the
// venue). density (may be null: D = 1) scales the number density. Above state.limit, a
// deterministic subset of exactly `limit` is kept, thinned evenly (wanted says how many more).
ParticleSet generateParticles(const ParticleState& state, const std::vector<ParticleCone>& cones,
                              const DensityField* density, const glm::vec3& boundsMin, const glm::vec3& boundsMax);

}  // namespace haze
