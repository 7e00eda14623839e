// The advection-diffusion of the hazers' haze: what it must keep (the total, without sinks),
// that it is deterministic, that the still part is what the spec says, and that the haze
// moves with the air.
#include <gtest/gtest.h>

#include <cmath>

#include "atmosphere/density_sim.h"

namespace haze {
namespace {

DensityGrid smallRoom() {
  DensityGrid g;
  g.n[0] = 32;
  g.n[1] = 16;
  g.n[2] = 32;
  g.minM = {-5, 0, -5};
  g.maxM = {5, 5, 5};
  return g;
}

DensitySpec twoHazers() {
  DensitySpec s;
  s.base = 0.5f;
  s.airFlowMps = {0.3f, 0.0f, -0.1f};
  s.mixingM2ps = 0.05f;
  s.hazers.push_back({.positionM = {-4, 0.5f, 4}, .direction = {1, 0.3f, -1}, .output = 0.8f, .spreadDeg = 30, .speedMps = 3});
  s.hazers.push_back({.positionM = {4, 0.2f, -4}, .direction = {-1, 0, 0}, .output = 0.4f, .spreadDeg = 60, .speedMps = 2});
  return s;
}

TEST(DensitySim, TotalHazeIsConservedWithinOnePercentOverAMinute) {
  DensitySim sim(twoHazers(), smallRoom());
  // Without sinks the grid holds exactly what the hazers put out: (0.8 + 0.4) m^3/s for 60 s.
  const double total = sim.hazeTotalAt(60.0);
  EXPECT_NEAR(total, 1.2 * 60.0, 0.01 * 1.2 * 60.0);
  // And at a time between steps.
  EXPECT_NEAR(sim.hazeTotalAt(60.0 + 0.37 * sim.stepS()), 1.2 * (60.0 + 0.37 * sim.stepS()), 0.01 * 72.0);
  // No cell goes negative, and the field is still part plus haze.
  const DensityField f = sim.fieldAt(60.0);
  double hazeInField = 0.0;
  for (float v : f.values) {
    EXPECT_GE(v, 0.5f);
    hazeInField += v - 0.5f;
  }
  EXPECT_NEAR(hazeInField * f.cellVolumeM3(), total, 1e-3 * total);
}

TEST(DensitySim, DissipationIsTheOnlySink) {
  DensitySpec s = twoHazers();
  s.dissipationPerS = 0.05f;
  DensitySim sim(s, smallRoom());
  // dM/dt = q - k M: M(t) = q / k (1 - exp(-k t)).
  const double expected = 1.2 / 0.05 * (1.0 - std::exp(-0.05 * 60.0));
  EXPECT_NEAR(sim.hazeTotalAt(60.0), expected, 0.02 * expected);
}

TEST(DensitySim, TheSameTimeGivesTheSameFieldHoweverItIsReached) {
  DensitySim a(twoHazers(), smallRoom()), b(twoHazers(), smallRoom());
  const DensityField direct = a.fieldAt(23.4);
  b.fieldAt(5.0);
  b.fieldAt(17.1);
  EXPECT_EQ(b.fieldAt(23.4).values, direct.values);
  b.fieldAt(40.0);
  EXPECT_EQ(b.fieldAt(23.4).values, direct.values);  // back in time: started over
}

TEST(DensitySim, StillPartIsBaseFogAndBoxes) {
  DensitySpec s;
  s.base = 0.2f;
  s.fog = FogLayerSpec{.density = 3.0f, .heightM = 1.0f, .falloffM = 0.5f};
  s.boxes.push_back({.minM = {2, 0, 2}, .maxM = {5, 5, 5}, .density = 4.0f});
  DensitySim sim(s, smallRoom());
  const DensityField f = sim.fieldAt(100.0);  // nothing moves without hazers
  // Cell (5, y, 5): centre x = z = -3.28; its y centres are 0.15625 + 0.3125 y.
  for (int y = 0; y < 16; ++y) {
    const float cy = f.cellCentre(5, y, 5).y;
    const float fog = cy <= 1.0f ? 3.0f : 3.0f * std::exp(-(cy - 1.0f) / 0.5f);
    EXPECT_NEAR(f.values[f.index(5, y, 5)], 0.2f + fog, 1e-5f) << y;
    EXPECT_FLOAT_EQ(f.values[f.index(28, y, 28)], 4.0f) << y;  // inside the box: its own density
  }
}

TEST(DensitySim, TheHazeDriftsWithTheAir) {
  DensitySpec s;
  s.base = 0.0f;
  s.mixingM2ps = 0.02f;
  s.airFlowMps = {0.25f, 0.0f, 0.0f};
  s.hazers.push_back({.positionM = {-3, 2, 0}, .direction = {0, 1, 0}, .output = 1.0f, .spreadDeg = 20, .speedMps = 0.2f});
  DensitySim sim(s, smallRoom());
  auto centroidX = [&](double t) {
    const DensityField f = sim.fieldAt(t);
    double m = 0, mx = 0;
    for (int z = 0; z < f.nz; ++z)
      for (int y = 0; y < f.ny; ++y)
        for (int x = 0; x < f.nx; ++x) {
          const double v = f.values[f.index(x, y, z)];
          m += v;
          mx += v * f.cellCentre(x, y, z).x;
        }
    return mx / m;
  };
  // Released at a steady rate from x = -3 and carried at 0.25 m/s, the haze's mean position
  // after 12 s lies about 0.25 * 12 / 2 = 1.5 m downwind (walls and diffusion aside).
  const double x12 = centroidX(12.0);
  EXPECT_GT(x12, -3.0 + 1.0);
  EXPECT_LT(x12, -3.0 + 2.0);
}

TEST(DensitySim, AHazerOutsideTheGridIsMovedInAndNamed) {
  DensitySpec s;
  s.hazers.push_back({.positionM = {0, 1, 0}});
  s.hazers.push_back({.positionM = {20, 1, 0}});
  DensitySim sim(s, smallRoom());
  ASSERT_EQ(sim.hazersClamped().size(), 1u);
  EXPECT_EQ(sim.hazersClamped()[0], 1);
  EXPECT_NEAR(sim.hazeTotalAt(10.0), 20.0, 0.2);  // both still put their haze into the room
}

}  // namespace
}  // namespace haze
