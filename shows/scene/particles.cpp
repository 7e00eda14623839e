#include "shows/scene/particles.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace haze {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A 32-bit integer hash with good avalanche (lowbias32, C. Wellons): the lattice's randomness.
uint32_t mix(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}
uint32_t cellHash(int64_t ix, int64_t iy, int64_t iz, uint32_t seed) {
  uint32_t h = mix(seed ^ 0x9e3779b9U);
  h = mix(h ^ static_cast<uint32_t>(ix));
  h = mix(h ^ static_cast<uint32_t>(iy) * 0x85ebca6bU);
  h = mix(h ^ static_cast<uint32_t>(iz) * 0xc2b2ae35U);
  return h;
}
// Uniform in [0, 1) from hash h and a stream number: every quantity of a particle has its own.
double uniform(uint32_t h, uint32_t stream) { return (mix(h ^ (stream * 0x27d4eb2dU)) >> 8) * (1.0 / 16777216.0); }

// The smallest k with P(N <= k) >= u for N ~ Poisson(lambda): monotonic in lambda for a fixed u,
// so a denser setting keeps every particle of a thinner one and adds more.
int poissonQuantile(double u, double lambda) {
  double p = std::exp(-lambda), cdf = p;
  int k = 0;
  while (u > cdf && k < 4096) {
    ++k;
    p *= lambda / k;
    cdf += p;
    if (p < 1e-300 && static_cast<double>(k) > lambda) break;
  }
  return k;
}

// Whether a ball meets the cone (apex a, unit axis z, half-angle with cos/sin, length L): the
// ball's centre's signed distance to the cone's side and to its two ends, conservative.
bool ballMeetsCone(const glm::dvec3& c, double radius, const ParticleCone& cone, double cosA, double sinA) {
  const glm::dvec3 d = c - glm::dvec3(cone.apex);
  const glm::dvec3 z(cone.axis);
  const double along = glm::dot(d, z);
  if (along < -radius || along > cone.lengthM + radius) return false;
  const double across = glm::length(d - along * z);
  return across * cosA - along * sinA <= radius;
}

bool insideCone(const glm::dvec3& x, const ParticleCone& cone, double cosA) {
  const glm::dvec3 d = x - glm::dvec3(cone.apex);
  const double along = glm::dot(d, glm::dvec3(cone.axis));
  if (along <= 0.0 || along > cone.lengthM) return false;
  return along >= cosA * glm::length(d);
}

}  // namespace

float settlingSpeedMps(float diameterUm) {
  // Stokes: v = rho g d^2 / (18 mu), rho 1000 kg/m^3, mu 1.8e-5 Pa s (air at 20 C).
  const double d = static_cast<double>(diameterUm) * 1e-6;
  return static_cast<float>(1000.0 * 9.81 * d * d / (18.0 * 1.8e-5));
}

glm::vec3 particleDrift(const ParticleSettings& settings, const glm::vec3& airFlowMps) {
  return airFlowMps - glm::vec3(0.0f, settlingSpeedMps(settings.sizeUm), 0.0f);
}

ParticleSet generateParticles(const ParticleState& state, const std::vector<ParticleCone>& cones,
                              const DensityField* density, const glm::vec3& boundsMin, const glm::vec3& boundsMax) {
  ParticleSet out;
  const ParticleSettings& ps = state.settings;
  if (!(ps.densityPerM3 > 0.0f) || cones.empty()) return out;
  const bool field = density && !density->empty();
  const double dMax = field ? static_cast<double>(density->maxValue()) : 1.0;
  if (!(dMax > 0.0)) return out;
  const double s = kParticleCellM;
  const double lambda = static_cast<double>(std::min(ps.densityPerM3, kMaxParticleDensityPerM3)) * s * s * s * dMax;
  const glm::dvec3 shift = glm::dvec3(particleDrift(ps, state.airFlowMps)) * state.timeS;  // the air frame's offset
  const double wobble = kParticleWobbleM;
  const double cellRadius = s * std::sqrt(3.0) * 0.5 + wobble * std::sqrt(3.0);
  const double twoPiT = 2.0 * kPi * state.timeS;
  // Per candidate: thinning hash (for the limit) and the entry.
  std::vector<std::pair<uint32_t, Particle>> found;

  for (const ParticleCone& cone : cones) {
    const double half = std::clamp(static_cast<double>(cone.halfAngleRad), 0.0, 1.5);
    const double cosA = std::cos(half), sinA = std::sin(half);
    const glm::dvec3 apex(cone.apex), axis(glm::normalize(cone.axis));
    const glm::dvec3 cap = apex + axis * static_cast<double>(cone.lengthM);
    const double capRadius = static_cast<double>(cone.lengthM) * std::tan(half);
    glm::dvec3 lo = glm::min(apex, cap), hi = glm::max(apex, cap);
    for (int k = 0; k < 3; ++k) {
      const double ext = capRadius * std::sqrt(std::max(0.0, 1.0 - axis[k] * axis[k]));
      lo[k] = std::max(std::min(lo[k], cap[k] - ext), static_cast<double>(boundsMin[k]));
      hi[k] = std::min(std::max(hi[k], cap[k] + ext), static_cast<double>(boundsMax[k]));
    }
    if (lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) continue;
    // Cells of the air frame whose particles can be inside this box now.
    const glm::dvec3 cLo = glm::floor((lo - shift - wobble) / s), cHi = glm::floor((hi - shift + wobble) / s);
    for (int64_t iz = static_cast<int64_t>(cLo.z); iz <= static_cast<int64_t>(cHi.z); ++iz)
      for (int64_t iy = static_cast<int64_t>(cLo.y); iy <= static_cast<int64_t>(cHi.y); ++iy)
        for (int64_t ix = static_cast<int64_t>(cLo.x); ix <= static_cast<int64_t>(cHi.x); ++ix) {
          const glm::dvec3 corner = glm::dvec3(ix, iy, iz) * s + shift;
          if (!ballMeetsCone(corner + 0.5 * s, cellRadius, cone, cosA, sinA)) continue;
          ++out.cellsTried;
          const uint32_t h = cellHash(ix, iy, iz, ps.seed);
          const int count = poissonQuantile(uniform(h, 0), lambda);
          for (int i = 0; i < count; ++i) {
            const uint32_t hp = mix(h + 0x632be5abU * static_cast<uint32_t>(i + 1));
            glm::dvec3 x = corner + glm::dvec3(uniform(hp, 1), uniform(hp, 2), uniform(hp, 3)) * s;
            for (int k = 0; k < 3; ++k) {
              const double f = 0.05 + 0.25 * uniform(hp, 4 + k);
              x[k] += wobble * std::sin(twoPiT * f + 2.0 * kPi * uniform(hp, 7 + k));
            }
            if (!insideCone(x, cone, cosA)) continue;
            if (x.x < boundsMin.x || x.y < boundsMin.y || x.z < boundsMin.z || x.x > boundsMax.x ||
                x.y > boundsMax.y || x.z > boundsMax.z)
              continue;
            if (field && uniform(hp, 10) * dMax >= static_cast<double>(density->sample(glm::vec3(x)))) continue;
            // Log-normal diameter (Box-Muller on two of the particle's uniforms).
            const double u1 = std::max(uniform(hp, 11), 1e-12), u2 = uniform(hp, 12);
            const double z = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
            const double dM = static_cast<double>(ps.sizeUm) * 1e-6 * std::exp(static_cast<double>(ps.sizeSigma) * z);
            Particle p{glm::vec3(x), static_cast<float>(kPi * dM * dM * 0.25), cone.beam};
            found.emplace_back(mix(hp ^ 0x5bd1e995U), p);
          }
        }
  }
  out.wanted = found.size();
  if (found.size() > state.limit) {
    // Thinned evenly over the whole frame (not the first cones first): the particles with the
    // smallest thinning hashes stay, so the subset is the same on every render.
    std::nth_element(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(state.limit), found.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    found.resize(state.limit);
  }
  out.particles.reserve(found.size());
  for (const auto& f : found) out.particles.push_back(f.second);
  return out;
}

}  // namespace haze
