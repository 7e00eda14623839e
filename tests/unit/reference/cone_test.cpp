// The ray/cone interval the reference marches over, against chords worked out by hand and
// against a dense inside/outside scan along random rays.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "renderer/reference/cone.h"

namespace haze {
namespace {

constexpr float kDeg = 3.14159265358979f / 180.0f;
const glm::vec3 kApex(0.0f, 5.0f, 0.0f);
const glm::vec3 kDown(0.0f, -1.0f, 0.0f);

TEST(Cone, PerpendicularChordIsTwiceHTanAlpha) {
  // A ray along +x at depth h = 3 below the apex: inside for |x| <= h tan(20 deg).
  const ConeInterval c = intersectCone({-10, 2, 0}, {1, 0, 0}, kApex, kDown, 20 * kDeg, 0, 100);
  ASSERT_FALSE(c.empty());
  const double half = 3.0 * std::tan(20.0 * 3.14159265358979 / 180.0);
  EXPECT_NEAR(c.t0, 10.0 - half, 1e-5);
  EXPECT_NEAR(c.t1, 10.0 + half, 1e-5);
}

TEST(Cone, CameraInsideTheCone) {
  // Looking straight down the axis from inside: the whole ray to tMax.
  ConeInterval c = intersectCone({0, 1, 0}, {0, -1, 0}, kApex, kDown, 10 * kDeg, 0, 7);
  EXPECT_DOUBLE_EQ(c.t0, 0.0);
  EXPECT_DOUBLE_EQ(c.t1, 7.0);
  // Looking up towards the lens: inside until the apex, then the back cone, which is dark.
  c = intersectCone({0, 1, 0}, {0, 1, 0}, kApex, kDown, 10 * kDeg, 0, 50);
  EXPECT_DOUBLE_EQ(c.t0, 0.0);
  EXPECT_NEAR(c.t1, 4.0, 1e-6);
  // Sideways from the axis at depth 4: out through the wall at 4 tan(10 deg).
  c = intersectCone({0, 1, 0}, {0, 0, 1}, kApex, kDown, 10 * kDeg, 0, 50);
  EXPECT_DOUBLE_EQ(c.t0, 0.0);
  EXPECT_NEAR(c.t1, 4.0 * std::tan(10.0 * 3.14159265358979 / 180.0), 1e-5);
}

TEST(Cone, BackConeIsEmpty) {
  // Crossing the quadric's other nappe, above the lens.
  EXPECT_TRUE(intersectCone({-10, 8, 0}, {1, 0, 0}, kApex, kDown, 30 * kDeg, 0, 100).empty());
  // Straight up the axis from above the lens.
  EXPECT_TRUE(intersectCone({0, 6, 0}, {0, 1, 0}, kApex, kDown, 30 * kDeg, 0, 100).empty());
  // From above, down through the lens: lit only below the apex.
  const ConeInterval c = intersectCone({0, 9, 0}, {0, -1, 0}, kApex, kDown, 30 * kDeg, 0, 100);
  EXPECT_NEAR(c.t0, 4.0, 1e-6);
  EXPECT_DOUBLE_EQ(c.t1, 100.0);
}

TEST(Cone, RayParallelToTheWall) {
  // Along a generator's direction, starting s to the side of the apex: inside from
  // t = s / (2 sin a) on, for ever (the quadric's leading coefficient is 0 here).
  const float a = 25 * kDeg;
  const glm::vec3 g(std::sin(a), -std::cos(a), 0.0f);
  const double s = 0.8;
  const ConeInterval c =
      intersectCone(kApex + glm::vec3(-float(s), 0, 0), g, kApex, kDown, a, 0, 1000);
  EXPECT_NEAR(c.t0, s / (2.0 * std::sin(double(a))), 1e-4);
  EXPECT_DOUBLE_EQ(c.t1, 1000.0);
}

TEST(Cone, ClippedToTheSegment) {
  const ConeInterval c = intersectCone({-10, 2, 0}, {1, 0, 0}, kApex, kDown, 20 * kDeg, 0, 9.5);
  EXPECT_NEAR(c.t0, 10.0 - 3.0 * std::tan(20.0 * 3.14159265358979 / 180.0), 1e-5);
  EXPECT_DOUBLE_EQ(c.t1, 9.5);
  EXPECT_TRUE(intersectCone({-10, 2, 0}, {1, 0, 0}, kApex, kDown, 20 * kDeg, 0, 8).empty());
}

TEST(Cone, MatchesADenseScanOnRandomRays) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int nonEmpty = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 apex(u(rng), 3.0f + u(rng), u(rng));
    const glm::vec3 axis = glm::normalize(glm::vec3(u(rng), -1.5f, u(rng)));
    const float half = (5.0f + 70.0f * (u(rng) + 1.0f) * 0.5f) * kDeg;
    const glm::vec3 o(4.0f * u(rng), 3.0f * u(rng) + 2.0f, 4.0f * u(rng));
    const glm::vec3 d = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
    const double tMax = 12.0;
    const ConeInterval c = intersectCone(o, d, apex, axis, half, 0.0, tMax);
    if (!c.empty()) ++nonEmpty;
    const double cosHalf = std::cos(double(half));
    for (int k = 0; k < 400; ++k) {
      const double t = tMax * (k + 0.5) / 400.0;
      const glm::dvec3 x = glm::dvec3(o) + t * glm::dvec3(d) - glm::dvec3(apex);
      const double along = glm::dot(x, glm::dvec3(axis));
      const double len = glm::length(x);
      // Skip points within a hair of the wall; elsewhere the interval must agree.
      if (std::fabs(along - len * cosHalf) < 1e-4) continue;
      const bool in = along > len * cosHalf;
      const bool inInterval = !c.empty() && t >= c.t0 && t <= c.t1;
      ASSERT_EQ(in, inInterval) << "ray " << i << " t " << t;
    }
  }
  EXPECT_GT(nonEmpty, 200);
}

}  // namespace
}  // namespace haze
