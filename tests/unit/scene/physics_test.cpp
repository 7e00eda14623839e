// physics.h against docs/physics.md: each phase function integrates to 1 over the sphere, HG's mean
// cosine is g, the hazy function's end values, and beamIntensityTowards' beam frame.
#include <gtest/gtest.h>

#include <cmath>

#include "shows/scene/physics.h"
#include "unit/scene/test_scenes.h"

namespace haze {
namespace {

// integral over the sphere of p(mu) * mu^power, by composite Simpson in mu = cos a
// (dOmega = 2 pi dmu).
double sphereIntegral(const MediumState& m, int power, int n = 200000) {
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double mu = -1.0 + 2.0 * i / n;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += w * phaseFunction(m, float(mu)) * std::pow(mu, power);
  }
  return 2.0 * test::kPiD * sum * (2.0 / n) / 3.0;
}

TEST(Physics, HazyPhaseIntegratesToOne) {
  MediumState m;
  m.phase = Phase::Hazy;
  EXPECT_NEAR(sphereIntegral(m, 0), 1.0, 1e-5);
  // p(a) = (1 + 9 cos^6(a/2)) / (13 pi): 10 / (13 pi) forward, 1 / (13 pi) backward.
  EXPECT_NEAR(phaseFunction(m, 1.0f), 10.0 / (13.0 * test::kPiD), 1e-6);
  EXPECT_NEAR(phaseFunction(m, -1.0f), 1.0 / (13.0 * test::kPiD), 1e-6);
  // At a = 90 degrees cos^6(45) = 1/8.
  EXPECT_NEAR(phaseFunction(m, 0.0f), (1.0 + 9.0 / 8.0) / (13.0 * test::kPiD), 1e-6);
}

TEST(Physics, IsotropicPhaseIntegratesToOne) {
  MediumState m;
  m.phase = Phase::Isotropic;
  EXPECT_NEAR(sphereIntegral(m, 0), 1.0, 1e-6);
  EXPECT_NEAR(sphereIntegral(m, 1), 0.0, 1e-6);
}

TEST(Physics, HenyeyGreensteinIntegratesToOneWithMeanCosineG) {
  for (float g : {-0.8f, -0.3f, 0.0f, 0.5f, 0.9f}) {
    MediumState m;
    m.phase = Phase::HenyeyGreenstein;
    m.g = g;
    EXPECT_NEAR(sphereIntegral(m, 0), 1.0, 1e-4) << "g " << g;
    EXPECT_NEAR(sphereIntegral(m, 1), g, 1e-4) << "g " << g;  // forward for g > 0
  }
}

TEST(Physics, BeamIntensityTowardsUsesTheBeamFrame) {
  // Parametric 20/40 beam pointing along +x from (1, 2, 3).
  const BeamState beam = test::makeBeam({1, 2, 3}, {1, 0, 0}, test::parametric(20, 40, 1000), 40,
                                        {1.0f, 0.5f, 0.25f});
  const glm::vec3 on = beamIntensityTowards(beam, {6, 2, 3});
  EXPECT_NEAR(on.r, 1000.0f, 1.0f);
  EXPECT_NEAR(on.g, 500.0f, 0.5f);  // colour filters per channel
  EXPECT_NEAR(on.b, 250.0f, 0.25f);
  // 10 degrees off the axis (the beam half-angle): 50 %; 20 degrees (field): 10 %; any azimuth.
  const float t10 = std::tan(10.0f * kPi / 180.0f), t20 = std::tan(20.0f * kPi / 180.0f);
  EXPECT_NEAR(beamIntensityTowards(beam, {3, 2 + 2 * t10, 3}).r, 500.0f, 5.0f);
  EXPECT_NEAR(beamIntensityTowards(beam, {3, 2, 3 - 2 * t10}).r, 500.0f, 5.0f);
  EXPECT_NEAR(beamIntensityTowards(beam, {3, 2 - 2 * t20, 3}).r, 100.0f, 1.0f);
  // Behind the lens, and at the lens itself, nothing.
  EXPECT_EQ(beamIntensityTowards(beam, {-4, 2, 3}), glm::vec3(0.0f));
  EXPECT_EQ(beamIntensityTowards(beam, {1, 2, 3}), glm::vec3(0.0f));
}

}  // namespace
}  // namespace haze
