// Beam optics beyond the gobo on a top-down floor render by the CPU reference, against
// docs/physics.md written out by hand: blades cut the pool along their lines (every pixel more
// than one pixel from a line is lit or dark as the line says), frost widens the pool's edge and
// keeps the flux on the floor within 2 %, a prism throws N pools of 1/N of the light each at the
// deflection angle; two gobo wheels multiply, the second turned by its own rotation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "fixtures/blades.h"
#include "fixtures/frost.h"
#include "fixtures/pose.h"
#include "fixtures/prism.h"
#include "renderer/reference/reference.h"
#include "unit/scene/test_scenes.h"

namespace haze {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kH = 4.0f;       // lamp height
constexpr float kCamH = 10.0f;   // camera height, looking straight down
constexpr float kFovDeg = 40.0f;
constexpr int kSize = 161;

// The floor point at the centre of pixel (i, j): docs/physics.md's pinhole, written out.
glm::vec2 floorAt(double i, double j) {
  const double t = std::tan(kFovDeg * 0.5 * kPi / 180.0) * kCamH;
  return {static_cast<float>(t * (2.0 * (i + 0.5) / kSize - 1.0)), static_cast<float>(-t * (1.0 - 2.0 * (j + 0.5) / kSize))};
}
double pixelMetres() { return 2.0 * std::tan(kFovDeg * 0.5 * kPi / 180.0) * kCamH / kSize; }

FrameState topDown() {
  FrameState f;
  f.camera.position = {0, kCamH, 0};
  f.camera.target = {0, 0, 0};
  f.camera.up = {0, 0, -1};
  f.camera.fovYDeg = kFovDeg;
  return f;
}

// A downlight: z_b = -Y, x_b = +X, y_b = -Z (docs/physics.md).
BeamState downlight(std::shared_ptr<const Distribution> d, float fieldDeg) {
  BeamState b = test::makeBeam({0, kH, 0}, {0, -1, 0}, std::move(d), fieldDeg);
  b.pose = beamFrame({0, kH, 0}, {0, -1, 0}, {1, 0, 0});
  return b;
}

ImageRGB render(const FrameState& f) {
  Venue v = test::emptyVenue();
  test::addFloor(v, 0.0f, 20.0f, test::addMaterial(v, glm::vec3(0.5f)));
  return renderReference(v, f, kSize, kSize);
}

// (u, v) of docs/physics.md for the floor point p under the downlight of field angle F.
glm::vec2 gateOf(glm::vec2 p, float fieldDeg) {
  const float t = std::tan(fieldDeg * 0.5f * static_cast<float>(kPi) / 180.0f);
  return {p.x / kH / t, -p.y / kH / t};
}

TEST(OpticsFloor, BladesCutThePoolAlongTheirLinesWithinAPixel) {
  const float field = 30.0f;
  FrameState f = topDown();
  BeamState b = downlight(test::uniformDistribution(25.0f, 5000.0f), field);
  BladeInsertions in{};
  in[0] = {0.25f, 0.25f};  // straight, at u = 0.5
  in[2] = {0.0f, 0.5f};    // slanted, from (-1, 1) to (0, -1)
  b.optics.blades = bladeMask(in, 20.0f);
  f.beams.push_back(b);
  const ImageRGB img = render(f);
  const BladeMask& m = b.optics.blades;
  // A pixel is checked when its whole footprint (one pixel around its centre) is on one side of
  // every line and inside or outside the 25-degree cone.
  const double px = pixelMetres();
  int lit = 0, cut = 0, checked = 0;
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      bool allLit = true, allDark = true;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const glm::vec2 p = floorAt(i + di, j + dj);
          const bool inCone = std::atan(std::hypot(p.x, p.y) / kH) < 25.0 * kPi / 180.0;
          const glm::vec2 g = gateOf(p, field);
          const bool on = inCone && m.transmittance(g.x, g.y) > 0.0f;
          allLit = allLit && on;
          allDark = allDark && !on;
        }
      if (!allLit && !allDark) continue;
      ++checked;
      const float value = img.at(i, j).g;
      if (allLit) {
        ++lit;
        EXPECT_GT(value, 0.0f) << i << ", " << j;
      } else {
        const glm::vec2 p = floorAt(i, j);
        if (std::atan(std::hypot(p.x, p.y) / kH) < 25.0 * kPi / 180.0) ++cut;
        EXPECT_EQ(value, 0.0f) << i << ", " << j;
      }
    }
  EXPECT_GT(lit, 1000);
  EXPECT_GT(cut, 1000);  // pixels inside the cone that the blades darken
  EXPECT_GT(checked, kSize * kSize * 9 / 10);
  std::printf("[ blades ] %d pixels checked, %d lit, %d cut inside the cone; pixel %.4f m\n", checked, lit, cut, px);
}

// Sum of pixel values (proportional to the flux on the floor) and the radius where the
// illuminance falls through 90 % and 10 % of the centre's, along +x.
struct Pool {
  double flux = 0;
  double r90 = 0, r10 = 0;
};
Pool measure(const ImageRGB& img) {
  Pool p;
  for (const glm::vec3& v : img.pixels) p.flux += v.g;
  const int c = kSize / 2;
  const double centre = img.at(c, c).g;
  for (int i = c; i < kSize; ++i) {
    const double v = img.at(i, c).g;
    if (p.r90 == 0 && v < 0.9 * centre) p.r90 = floorAt(i, c).x;
    if (p.r10 == 0 && v < 0.1 * centre) p.r10 = floorAt(i, c).x;
  }
  return p;
}

TEST(OpticsFloor, FrostWidensTheEdgeAndKeepsTheFlux) {
  auto d = test::parametric(12.0f, 18.0f, 20000.0f);
  FrameState sharp = topDown();
  sharp.beams.push_back(downlight(d, 18.0f));
  FrameState soft = topDown();
  soft.beams.push_back(downlight(frosted(d, 3.0f), 18.0f));
  const Pool a = measure(render(sharp)), b = measure(render(soft));
  EXPECT_NEAR(b.flux / a.flux, 1.0, 0.02);
  // The edge (90 % to 10 %) is wider by more than three pixels (measured: 0.18 m, 4 pixels,
  // against 2.56 sigma h = 0.54 m for a step edge blurred alone: the beam's own edge is soft).
  EXPECT_GT((b.r10 - b.r90) - (a.r10 - a.r90), 3.0 * pixelMetres());
  EXPECT_GT(b.r10, a.r10);
}

TEST(OpticsFloor, PrismThrowsThreeAndFivePoolsAtTheDeflection) {
  auto d = test::parametric(5.0f, 8.0f, 200000.0f);
  FrameState plain = topDown();
  plain.beams.push_back(downlight(d, 8.0f));
  const double total = measure(render(plain)).flux;
  for (int n : {3, 5}) {
    const PrismSpec prism{"p", n, 20.0f, false};
    const float rot = 15.0f;
    FrameState f = topDown();
    const BeamState one = downlight(d, 8.0f);
    for (const BeamPose& pose : prismCopies(one.pose, prism, rot)) {
      BeamState copy = one;
      copy.pose = pose;
      copy.optics.dimmer = 1.0f / static_cast<float>(n);
      f.beams.push_back(copy);
    }
    const ImageRGB img = render(f);
    // Each sector around copy j's azimuth holds one pool, centred h tan(delta) out, 1/N of the light.
    const double reach = kH * std::tan(20.0 * kPi / 180.0);
    for (int j = 0; j < n; ++j) {
      const double psi = (rot + 360.0 * j / n) * kPi / 180.0;
      // x_b = +X, y_b = -Z: the floor point at azimuth psi is (cos psi, -sin psi).
      const glm::vec2 want(static_cast<float>(reach * std::cos(psi)), static_cast<float>(-reach * std::sin(psi)));
      double sum = 0, sx = 0, sy = 0;
      for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
          const glm::vec2 p = floorAt(x, y);
          if (glm::length(p - want) > reach * std::sin(kPi / n)) continue;  // this copy's disc
          const double v = img.at(x, y).g;
          sum += v;
          sx += v * p.x;
          sy += v * p.y;
        }
      EXPECT_NEAR(sum / total, 1.0 / n, 0.02 / n) << n << " facets, copy " << j;
      // The centroid sits a little beyond the axis' hit point (the far side is hit more
      // obliquely but is larger); within 3 % of the reach.
      EXPECT_NEAR(std::hypot(sx / sum - want.x, sy / sum - want.y), 0.0, 0.03 * reach) << n << ", " << j;
    }
  }
}

// An 8 x 8 gobo: the left half (s < 0.5) passes `left`, the right half `right`.
std::shared_ptr<GoboImage> halves(float left, float right) {
  auto g = std::make_shared<GoboImage>();
  g->width = g->height = 8;
  g->transmittance.resize(64);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) g->transmittance[static_cast<size_t>(j * 8 + i)] = i < 4 ? left : right;
  return g;
}

TEST(OpticsFloor, TwoGobosMultiplyAndTheSecondTurnsOnItsOwn) {
  const float field = 30.0f;
  const BeamState open = downlight(test::uniformDistribution(25.0f, 5000.0f), field);
  auto withGobos = [&](std::shared_ptr<const GoboImage> g1, std::shared_ptr<const GoboImage> g2) {
    FrameState f = topDown();
    BeamState b = open;
    b.optics.iris = 0.999f;  // gated as with a gobo in, so every image has the same cone
    b.optics.gobo = std::move(g1);
    b.optics.gobo2 = std::move(g2);
    b.optics.gobo2RotationDeg = 90.0f;
    f.beams.push_back(b);
    return render(f);
  };
  const ImageRGB none = withGobos(nullptr, nullptr);
  const ImageRGB first = withGobos(halves(1.0f, 0.5f), nullptr);
  const ImageRGB both = withGobos(halves(1.0f, 0.5f), halves(0.8f, 0.25f));
  // By hand: gobo 1 passes 1 at u < 0 and 0.5 at u > 0. Gobo 2 turned +90 degrees shows at gate
  // point (u, v) its image point turned back, (v, -u): its s runs with v, so it passes 0.8 at
  // v < 0 and 0.25 at v > 0. The bilinear lookup blends across the halves' middle pixel pair,
  // |u| or |v| < 1/8; pixels whose whole footprint is clear of that and inside the gate are checked.
  const double quadrant[2][2] = {{1.0 * 0.8, 1.0 * 0.25}, {0.5 * 0.8, 0.5 * 0.25}};  // [u > 0][v > 0]
  int checked = 0;
  double withSum = 0, withoutSum = 0;
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      withSum += both.at(i, j).g;
      withoutSum += first.at(i, j).g;
      int qu = -1, qv = -1;
      bool clear = true;
      for (int dj = -1; dj <= 1 && clear; ++dj)
        for (int di = -1; di <= 1 && clear; ++di) {
          const glm::vec2 g = gateOf(floorAt(i + di, j + dj), field);
          const int u = g.x > 0.0f, v = g.y > 0.0f;
          clear = std::abs(g.x) > 0.13f && std::abs(g.y) > 0.13f && std::hypot(g.x, g.y) < 0.95f && (qu < 0 || (qu == u && qv == v));
          qu = u;
          qv = v;
        }
      if (!clear) continue;
      ++checked;
      const double o = none.at(i, j).g;
      ASSERT_GT(o, 0.0) << i << ", " << j;
      EXPECT_NEAR(both.at(i, j).g / o, quadrant[qu][qv], 1e-4) << i << ", " << j;
      EXPECT_NEAR(first.at(i, j).g / o, qu ? 0.5 : 1.0, 1e-4) << i << ", " << j;
    }
  EXPECT_GT(checked, 500);  // measured 736: the pool is about 48 pixels across
  // The whole pool, by symmetry (the uniform beam's four quadrants hold equal light): with both
  // gobos (0.8 + 0.25 + 0.4 + 0.125) / 4 = 0.39375 of the open pool, with the first alone 0.75.
  EXPECT_NEAR(withSum / withoutSum, 0.39375 / 0.75, 0.01);
  std::printf("[ two gobos ] %d pixels checked; pool with gobo 2 / without: %.4f\n", checked, withSum / withoutSum);
}

}  // namespace
}  // namespace haze
