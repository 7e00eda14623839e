// The reference's BVH against a brute-force double-precision ray/plane + edge-side test over
// every triangle, plus the robustness cases: shared edges, degenerate and non-finite triangles,
// segment limits for shadow rays.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "shows/scene/bvh.h"
#include "unit/scene/test_scenes.h"

namespace haze {
namespace {

using test::addBox;
using test::addFloor;
using test::addQuad;
using test::addUvSphere;
using test::emptyVenue;

struct Brute {
  double t = INFINITY;
  double margin = 0.0;  // how far inside its triangle the hit is (edge-side distance / edge)
};

// Independent of the BVH's Moeller-Trumbore: intersect the triangle's plane, then test the
// point against the three edges' sides, in double.
Brute bruteForce(const Venue& v, glm::dvec3 o, glm::dvec3 d) {
  Brute best;
  for (const Primitive& p : v.primitives) {
    for (size_t k = 0; k + 2 < p.indices.size(); k += 3) {
      const glm::dvec3 a(p.positions[p.indices[k]]), b(p.positions[p.indices[k + 1]]),
          c(p.positions[p.indices[k + 2]]);
      const glm::dvec3 n = glm::cross(b - a, c - a);
      const double dn = glm::dot(d, n);
      if (std::fabs(dn) < 1e-15) continue;
      const double t = glm::dot(a - o, n) / dn;
      if (t <= 0.0 || t >= best.t) continue;
      const glm::dvec3 x = o + t * d;
      const double s0 = glm::dot(glm::cross(b - a, x - a), n);
      const double s1 = glm::dot(glm::cross(c - b, x - b), n);
      const double s2 = glm::dot(glm::cross(a - c, x - c), n);
      if (s0 < 0 || s1 < 0 || s2 < 0) continue;
      best.t = t;
      const double nl = glm::length(n);
      best.margin = std::min({s0 / (nl * glm::length(b - a)), s1 / (nl * glm::length(c - b)),
                              s2 / (nl * glm::length(a - c))});
    }
  }
  return best;
}

Venue clutter() {
  Venue v = emptyVenue();
  addFloor(v, 0.0f, 10.0f);
  addBox(v, {-2, 0, -1}, {-1, 2, 1});
  addBox(v, {1.5f, 0.5f, -3}, {3, 1, 2});
  addUvSphere(v, {0, 1.5f, 2}, 1.0f, 16, 32);
  addUvSphere(v, {-3, 3, -3}, 0.5f, 8, 16);
  return v;
}

TEST(Bvh, ClosestHitMatchesBruteForceOnRandomRays) {
  const Venue v = clutter();
  const Bvh bvh(v);
  ASSERT_EQ(bvh.triangleCount(), v.triangleCount());
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int hits = 0, compared = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 o(6.0f * u(rng), 0.2f + 4.0f * (u(rng) + 1.0f), 6.0f * u(rng));
    const glm::vec3 d = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0, -0.3f, 0));
    const Brute ref = bruteForce(v, o, d);
    // Rays within a hair of an edge may go either way in float; compare the clear cases.
    if (std::isfinite(ref.t) && ref.margin < 1e-4) continue;
    ++compared;
    const RayHit h = bvh.closestHit(o, d, 0.0f, 1e30f);
    ASSERT_EQ(h.hit(), std::isfinite(ref.t)) << "ray " << i;
    if (!h.hit()) continue;
    ++hits;
    EXPECT_NEAR(h.tM, ref.t, 1e-4 * (1.0 + ref.t)) << "ray " << i;
    // The barycentrics put the hit back on the ray.
    const SurfacePoint s = bvh.surfaceAt(h);
    const glm::vec3 x = o + h.tM * d;
    EXPECT_NEAR(glm::length(s.positionM - x), 0.0f, 1e-4f) << "ray " << i;
  }
  EXPECT_GT(compared, 1900);
  EXPECT_GT(hits, 600);  // the rays mostly point at the scene: a real comparison
}

TEST(Bvh, TreeIsShallowForManyTriangles) {
  Venue v = emptyVenue();
  addUvSphere(v, {0, 0, 0}, 1.0f, 100, 200);  // ~40k triangles
  const Bvh bvh(v);
  EXPECT_GT(bvh.triangleCount(), 39000u);
  EXPECT_LT(bvh.depth(), 40);
  const RayHit h = bvh.closestHit({0, 0, 5}, {0, 0, -1}, 0.0f, 100.0f);
  ASSERT_TRUE(h.hit());
  EXPECT_NEAR(h.tM, 4.0f, 1e-3f);  // the tessellated sphere's vertex ring at the equator
}

TEST(Bvh, RaysThroughSharedEdgesNeverSlipThrough) {
  Venue v = emptyVenue();
  addFloor(v, 0.0f, 1.0f);  // diagonal from (-1, -1) to (1, 1) in x, z
  const Bvh bvh(v);
  for (int i = 0; i <= 1000; ++i) {
    const float s = -0.999f + 1.998f * float(i) / 1000.0f;
    // Straight down exactly onto the shared diagonal, and slanted through it.
    EXPECT_TRUE(bvh.closestHit({s, 2.0f, s}, {0, -1, 0}, 0.0f, 10.0f).hit()) << s;
    const glm::vec3 d = glm::normalize(glm::vec3(0.3f, -1.0f, 0.3f));
    EXPECT_TRUE(bvh.closestHit(glm::vec3(s, 0, s) - 2.0f * d, d, 0.0f, 10.0f).hit()) << s;
  }
}

// mayComeNear (the reference's soft-shadow early out): false only when no triangle is within
// the radius of the segment; a segment 0.1 m above a floor is near at 0.15 m, not at 0.05 m,
// and one that ends 0.1 m short of the floor's edge is near only past 0.1 m.
TEST(Bvh, MayComeNearSeesTrianglesWithinTheRadiusOfASegment) {
  Venue v = emptyVenue();
  addFloor(v, 0.0f, 1.0f);  // |x|, |z| <= 1 at y = 0
  const Bvh bvh(v);
  EXPECT_FALSE(bvh.mayComeNear({-0.5f, 0.1f, 0.0f}, {1, 0, 0}, 0.0f, 1.0f, 0.05f));
  EXPECT_TRUE(bvh.mayComeNear({-0.5f, 0.1f, 0.0f}, {1, 0, 0}, 0.0f, 1.0f, 0.15f));
  EXPECT_FALSE(bvh.mayComeNear({1.1f, -0.5f, 0.0f}, {0, 1, 0}, 0.0f, 1.0f, 0.09f));  // beside the edge
  EXPECT_TRUE(bvh.mayComeNear({1.1f, -0.5f, 0.0f}, {0, 1, 0}, 0.0f, 1.0f, 0.11f));
  EXPECT_FALSE(bvh.mayComeNear({0.0f, 0.5f, 0.0f}, {0, 1, 0}, 0.0f, 1.0f, 0.4f));  // above it, short
  EXPECT_TRUE(bvh.mayComeNear({0.0f, 0.5f, 0.0f}, {0, 1, 0}, -1.0f, 1.0f, 0.0f));  // through it
}

TEST(Bvh, BackFacesAreHitAndGeometryIsReported) {
  Venue v = emptyVenue();
  addFloor(v, 1.0f, 2.0f);  // faces up
  const Bvh bvh(v);
  const RayHit h = bvh.closestHit({0.5f, 0.0f, 0.25f}, {0, 1, 0}, 0.0f, 10.0f);  // from below
  ASSERT_TRUE(h.hit());
  EXPECT_NEAR(h.tM, 1.0f, 1e-6f);
  EXPECT_EQ(h.primitive, 0);
  const SurfacePoint s = bvh.surfaceAt(h);
  EXPECT_NEAR(s.geometricNormal.y, 1.0f, 1e-6f);  // the winding normal, whatever the side
  EXPECT_NEAR(s.shadingNormal.y, 1.0f, 1e-6f);
  // addQuad's uvs put u = (z + 2) / 4 and v = (x + 2) / 4 on this floor.
  EXPECT_NEAR(s.uv.x, 0.5625f, 1e-5f);
  EXPECT_NEAR(s.uv.y, 0.625f, 1e-5f);
}

TEST(Bvh, AnyHitHonoursTheSegment) {
  Venue v = emptyVenue();
  addFloor(v, 0.0f, 5.0f);
  const Bvh bvh(v);
  const glm::vec3 o(0, 3, 0), d(0, -1, 0);
  EXPECT_TRUE(bvh.anyHit(o, d, 0.0f, 3.5f));
  EXPECT_FALSE(bvh.anyHit(o, d, 0.0f, 2.9f));   // stops short of the floor
  EXPECT_FALSE(bvh.anyHit(o, d, 3.1f, 10.0f));  // starts past it
  EXPECT_FALSE(bvh.anyHit(o, -d, 0.0f, 10.0f)); // points away
  // A closest hit with tMax before the floor is a miss too.
  EXPECT_FALSE(bvh.closestHit(o, d, 0.0f, 2.0f).hit());
}

TEST(Bvh, DegenerateAndNonFiniteTrianglesAreHarmless) {
  Venue v = emptyVenue();
  Primitive bad;
  const float nan = std::nanf("");
  bad.positions = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0},        // a point
                   {-1, 1, 0}, {0, 1, 0}, {1, 1, 0},       // a line across the ray's path
                   {nan, 1, 0}, {1, 1, 1}, {-1, 1, 1},     // NaN vertex
                   {INFINITY, 1, 0}, {1, 1, -1}, {-1, 1, 1}};
  bad.indices = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 0, 1, 99};  // 99: out of range
  v.primitives.push_back(bad);
  addFloor(v, 0.0f, 2.0f);
  const Bvh bvh(v);
  EXPECT_EQ(bvh.triangleCount(), 2u + 2u);  // point, line, and the floor's two
  for (const glm::vec3& o : {glm::vec3(0, 2, 0), glm::vec3(0.0f, 2.0f, 0.0001f)}) {
    const RayHit h = bvh.closestHit(o, {0, -1, 0}, 0.0f, 10.0f);
    ASSERT_TRUE(h.hit());
    EXPECT_EQ(h.primitive, 1);  // the floor, through the degenerate ones
    EXPECT_NEAR(h.tM, 2.0f, 1e-6f);
    EXPECT_TRUE(std::isfinite(h.b1) && std::isfinite(h.b2));
  }
  // Non-finite rays are a miss, not a crash.
  EXPECT_FALSE(bvh.closestHit({nan, 0, 0}, {0, -1, 0}, 0.0f, 10.0f).hit());
  EXPECT_FALSE(bvh.anyHit({0, 2, 0}, {0, nan, 0}, 0.0f, 10.0f));
}

TEST(Bvh, HugeCoordinatesBuildAndMiss) {
  // Finite but near float's limit: the build's arithmetic overflows to inf, which must not
  // reach an integer cast or the tree's depth.
  Venue v = emptyVenue();
  Primitive p;
  for (int i = 0; i < 64; ++i) {
    const float s = (i % 2 ? 3e38f : -3e38f);
    p.positions.push_back({s, float(i), 0});
    p.positions.push_back({s, float(i), 1});
    p.positions.push_back({-s, float(i), 1});
    p.indices.insert(p.indices.end(), {uint32_t(3 * i), uint32_t(3 * i + 1), uint32_t(3 * i + 2)});
  }
  v.primitives.push_back(p);
  addFloor(v, -5.0f, 1.0f);
  const Bvh bvh(v);
  EXPECT_EQ(bvh.triangleCount(), 66u);
  EXPECT_LT(bvh.depth(), 20);
  const RayHit h = bvh.closestHit({0.5f, -4.0f, 0.5f}, {0, -1, 0}, 0.0f, 10.0f);
  ASSERT_TRUE(h.hit());
  EXPECT_NEAR(h.tM, 1.0f, 1e-5f);
}

TEST(Bvh, EmptyVenue) {
  const Venue v = emptyVenue();
  const Bvh bvh(v);
  EXPECT_EQ(bvh.triangleCount(), 0u);
  EXPECT_FALSE(bvh.closestHit({0, 0, 0}, {0, 0, 1}, 0.0f, 100.0f).hit());
  EXPECT_FALSE(bvh.anyHit({0, 0, 0}, {0, 0, 1}, 0.0f, 100.0f));
}

}  // namespace
}  // namespace haze
