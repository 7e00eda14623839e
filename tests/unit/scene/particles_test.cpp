// The particles' placement (shows/scene/particles.h): stable for a seed and time, moving with
// the air, only inside the cones, as many as the density asks, thinned to the limit.
#include <cmath>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "shows/scene/particles.h"

namespace haze {
namespace {

ParticleState state(float density = 200.0f, double timeS = 0.0) {
  ParticleState s;
  s.settings.enabled = true;
  s.settings.densityPerM3 = density;
  s.timeS = timeS;
  return s;
}

// A spot 6 m up pointing down, half-angle 12 degrees, lighting 6 m.
std::vector<ParticleCone> spot() {
  return {{.apex = {0.0f, 6.0f, 0.0f}, .axis = {0.0f, -1.0f, 0.0f}, .halfAngleRad = 0.21f, .lengthM = 6.0f, .beam = 3}};
}
const glm::vec3 kLo(-10.0f, 0.0f, -10.0f), kHi(10.0f, 10.0f, 10.0f);

double coneVolume(const ParticleCone& c) {
  const double r = c.lengthM * std::tan(c.halfAngleRad);
  return 3.14159265358979 * r * r * c.lengthM / 3.0;
}

TEST(Particles, SameSeedAndTimeGiveTheSameParticles) {
  const ParticleSet a = generateParticles(state(200, 12.5), spot(), nullptr, kLo, kHi);
  const ParticleSet b = generateParticles(state(200, 12.5), spot(), nullptr, kLo, kHi);
  ASSERT_GT(a.particles.size(), 100u);
  ASSERT_EQ(a.particles.size(), b.particles.size());
  for (size_t i = 0; i < a.particles.size(); ++i) {
    EXPECT_EQ(a.particles[i].positionM, b.particles[i].positionM);
    EXPECT_EQ(a.particles[i].crossSectionM2, b.particles[i].crossSectionM2);
  }
  ParticleState other = state(200, 12.5);
  other.settings.seed = 2;
  const ParticleSet c = generateParticles(other, spot(), nullptr, kLo, kHi);
  EXPECT_NE(c.particles.front().positionM, a.particles.front().positionM);
}

TEST(Particles, AllLieInsideTheConeAndBeamIsTheCones) {
  const ParticleCone cone = spot()[0];
  const ParticleSet set = generateParticles(state(), spot(), nullptr, kLo, kHi);
  ASSERT_FALSE(set.particles.empty());
  for (const Particle& p : set.particles) {
    const glm::vec3 d = p.positionM - cone.apex;
    const float along = glm::dot(d, cone.axis);
    EXPECT_GT(along, 0.0f);
    EXPECT_LE(along, cone.lengthM + 1e-4f);
    EXPECT_GE(along, std::cos(cone.halfAngleRad) * glm::length(d) - 1e-5f);
    EXPECT_EQ(p.beam, 3);
  }
}

TEST(Particles, CountFollowsTheDensity) {
  // Poisson counts over the cone: within a few standard deviations of n V.
  const double volume = coneVolume(spot()[0]);
  for (float n : {50.0f, 200.0f, 800.0f}) {
    const double got = static_cast<double>(generateParticles(state(n), spot(), nullptr, kLo, kHi).particles.size());
    const double expected = n * volume;
    EXPECT_NEAR(got, expected, 4.0 * std::sqrt(expected) + 0.02 * expected) << n;
  }
  // A denser setting keeps the thinner one's particles and adds more.
  const ParticleSet thin = generateParticles(state(100), spot(), nullptr, kLo, kHi);
  const ParticleSet thick = generateParticles(state(400), spot(), nullptr, kLo, kHi);
  size_t kept = 0;
  for (const Particle& p : thin.particles)
    for (const Particle& q : thick.particles)
      if (p.positionM == q.positionM) { ++kept; break; }
  EXPECT_EQ(kept, thin.particles.size());
}

TEST(Particles, DensityFieldScalesTheCount) {
  // D = 2 over the left half (x < 0) and 0.5 on the right: four times as many on the left.
  DensityField f = DensityField::filled(2, 1, 1, {-10.0f, 0.0f, -10.0f}, {10.0f, 10.0f, 10.0f}, 0.5f);
  f.values[0] = 2.0f;
  // Nearest-edge outside, trilinear inside: D falls from 2 to 0.5 between the cell centres at
  // x = -5 and 5, so compare two horizontal beams around x = -8.5 and x = 8.5.
  std::vector<ParticleCone> cones = {
      {.apex = {-8.5f, 5.0f, 0.0f}, .axis = {0.0f, 0.0f, 1.0f}, .halfAngleRad = 0.3f, .lengthM = 5.0f, .beam = 0},
      {.apex = {8.5f, 5.0f, 0.0f}, .axis = {0.0f, 0.0f, 1.0f}, .halfAngleRad = 0.3f, .lengthM = 5.0f, .beam = 1}};
  const ParticleSet set = generateParticles(state(400), cones, &f, kLo, kHi);
  double left = 0, right = 0;
  for (const Particle& p : set.particles) (p.beam == 0 ? left : right) += 1;
  ASSERT_GT(right, 50);
  EXPECT_NEAR(left / right, 4.0, 0.8);
}

TEST(Particles, TheyMoveWithTheAir) {
  ParticleState a = state(200, 10.0), b = state(200, 10.0);
  a.airFlowMps = b.airFlowMps = {0.3f, 0.0f, 0.0f};
  b.timeS = 11.0;
  // A cone wide enough that most particles are inside at both times.
  std::vector<ParticleCone> big = {
      {.apex = {0.0f, 9.0f, 0.0f}, .axis = {0.0f, -1.0f, 0.0f}, .halfAngleRad = 0.6f, .lengthM = 9.0f, .beam = 0}};
  const ParticleSet pa = generateParticles(a, big, nullptr, kLo, kHi);
  const ParticleSet pb = generateParticles(b, big, nullptr, kLo, kHi);
  // Each particle of the earlier frame is found again one second on, displaced by the drift
  // (0.3 m in x, the settling in -y) within the wobble's reach.
  const glm::vec3 drift = particleDrift(a.settings, a.airFlowMps);
  EXPECT_LT(drift.y, -0.01f);
  size_t matched = 0, tried = 0;
  for (size_t i = 0; i < pa.particles.size(); i += 37) {
    ++tried;
    const glm::vec3 want = pa.particles[i].positionM + drift;
    for (const Particle& q : pb.particles)
      if (glm::length(q.positionM - want) < 2.0f * std::sqrt(3.0f) * kParticleWobbleM &&
          q.crossSectionM2 == pa.particles[i].crossSectionM2) {
        ++matched;
        break;
      }
  }
  EXPECT_GT(tried, 20u);
  EXPECT_GE(static_cast<double>(matched), 0.9 * static_cast<double>(tried));
  // and they did move.
  size_t same = 0;
  for (size_t i = 0; i < pa.particles.size(); i += 37)
    for (const Particle& q : pb.particles)
      if (pa.particles[i].positionM == q.positionM) ++same;
  EXPECT_EQ(same, 0u);
}

TEST(Particles, SizesAreLogNormal) {
  ParticleState s = state(2000);
  s.settings.sizeUm = 40.0f;
  s.settings.sizeSigma = 0.5f;
  const ParticleSet set = generateParticles(s, spot(), nullptr, kLo, kHi);
  ASSERT_GT(set.particles.size(), 2000u);
  double sum = 0, sum2 = 0;
  for (const Particle& p : set.particles) {
    const double d = std::sqrt(4.0 * p.crossSectionM2 / 3.14159265358979) * 1e6;  // um
    sum += std::log(d);
    sum2 += std::log(d) * std::log(d);
  }
  const double n = static_cast<double>(set.particles.size());
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(std::exp(mean), 40.0, 1.5);
  EXPECT_NEAR(sd, 0.5, 0.03);
}

TEST(Particles, TheLimitThinsAndSaysHowManyWereWanted) {
  ParticleState s = state(800);
  const size_t all = generateParticles(s, spot(), nullptr, kLo, kHi).particles.size();
  s.limit = all / 4;
  const ParticleSet set = generateParticles(s, spot(), nullptr, kLo, kHi);
  EXPECT_EQ(set.wanted, all);
  EXPECT_EQ(set.particles.size(), all / 4);
}

TEST(Particles, NoDensityOrNoConeGivesNone) {
  EXPECT_TRUE(generateParticles(state(0), spot(), nullptr, kLo, kHi).particles.empty());
  EXPECT_TRUE(generateParticles(state(200), {}, nullptr, kLo, kHi).particles.empty());
}

}  // namespace
}  // namespace haze
