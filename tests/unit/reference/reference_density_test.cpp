// The reference with a density field (docs/physics.md, section 9): D = 1 everywhere is the
// uniform medium, a surface behind a dense slab is dimmed by the closed form of its optical
// path, and L_in along rays through a non-uniform field matches a quadrature written out here
// (D from the field's own sample, every transmittance its own Simpson integral).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "renderer/reference/reference.h"
#include "unit/scene/test_scenes.h"

namespace haze {
namespace {

using test::kPiD;

FrameState slabScene(Venue& v) {
  v = test::emptyVenue();
  const int grey = test::addMaterial(v, glm::vec3(0.5f));
  test::addFloor(v, 0.0f, 10.0f, grey);
  test::addUvSphere(v, {0, 2.8f, 0}, 0.35f, 12, 24, grey);
  FrameState f;
  f.camera.position = {0.5f, 2.0f, 7.0f};
  f.camera.target = {0, 2.0f, 0};
  f.camera.fovYDeg = 55.0f;
  f.medium.scattering = 0.05f;
  f.medium.absorption = 0.01f;
  f.medium.background = glm::vec3(0.3f);
  f.beams.push_back(test::makeBeam({0, 5, 0}, {0, -1, 0}, test::parametric(15, 25, 20000), 25));
  f.beams.push_back(test::makeBeam({-3, 4.5f, -1}, {0.8f, -0.5f, 0.3f}, test::parametric(8, 14, 40000), 14,
                                   {0.2f, 0.6f, 1.0f}));
  return f;
}

TEST(ReferenceDensity, OneEverywhereIsTheUniformMedium) {
  Venue v;
  FrameState f = slabScene(v);
  const Bvh bvh(v);
  const ReferenceImages uniform = renderReferenceImages(bvh, f, 32, 24);
  f.medium.density = std::make_shared<DensityField>(DensityField::filled(16, 8, 16, {-6, 0, -6}, {6, 6, 8}, 1.0f));
  const ReferenceImages ones = renderReferenceImages(bvh, f, 32, 24);
  float worst = 0.0f, peak = 0.0f;
  for (const glm::vec3& p : uniform.total.pixels) peak = std::max(peak, p.r);
  for (size_t k = 0; k < uniform.total.pixels.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      const float a = uniform.total.pixels[k][c], b = ones.total.pixels[k][c];
      worst = std::max(worst, std::fabs(a - b) / std::max(a, 1e-6f * peak));
    }
  EXPECT_LT(worst, 1e-5f);  // float rounding of the path integrals, nothing more
}

TEST(ReferenceDensity, ASlabDimsTheFloorByItsOpticalPath) {
  // A 1 m slab of D = 3 at y in [2, 3] on a grid of 1 m cells: its cell centre 2.5 holds 3, its
  // neighbours 1, so D rises linearly from 1.5 to 2.5 and falls to 3.5, adding 2 to the integral of
  // D along any vertical line across it (a triangle of base 2 and height 2).
  Venue v = test::emptyVenue();
  const int grey = test::addMaterial(v, glm::vec3(0.5f));
  test::addFloor(v, 0.0f, 20.0f, grey);
  const Bvh bvh(v);
  FrameState f;
  f.medium.scattering = 0.05f;
  f.medium.absorption = 0.02f;
  const float cd = 1000.0f;
  f.beams.push_back(test::makeBeam({0, 5, 0}, {0, -1, 0}, test::uniformDistribution(20, cd), 40));
  DensityField slab = DensityField::filled(10, 7, 10, {-5, 0, -5}, {5, 7, 5}, 1.0f);
  for (int z = 0; z < 10; ++z)
    for (int x = 0; x < 10; ++x) slab.values[slab.index(x, 2, z)] = 3.0f;
  f.medium.density = std::make_shared<DensityField>(slab);
  const glm::vec3 eye(0.0f, 6.5f, 0.0f);  // above the lens, looking straight down through it
  const PixelRadiance p = radianceAlongRay(bvh, f, eye, {0, -1, 0});
  ASSERT_TRUE(p.hitSurface);
  const double sigmaT = 0.07;
  const double expected = 0.5 / kPiD * cd / 25.0 * std::exp(-sigmaT * (5.0 + 2.0)) * std::exp(-sigmaT * (6.5 + 2.0));
  EXPECT_NEAR(p.surface.r, expected, 1e-4 * expected);
}

// A field with a plume-like lump: D = 0.2 + 4 exp(-|x - c|^2 / 2) on 1/3 m cells, and a fog layer.
std::shared_ptr<const DensityField> lumpyField() {
  DensityField f = DensityField::filled(30, 21, 30, {-5, 0, -5}, {5, 7, 5}, 0.0f);
  for (int z = 0; z < f.nz; ++z)
    for (int y = 0; y < f.ny; ++y)
      for (int x = 0; x < f.nx; ++x) {
        const glm::vec3 p = f.cellCentre(x, y, z);
        const glm::vec3 d = p - glm::vec3(0.8f, 2.5f, -0.3f);
        f.values[f.index(x, y, z)] = 0.2f + 4.0f * std::exp(-glm::dot(d, d) / 2.0f) + (p.y < 0.6f ? 3.0f : 0.0f);
      }
  return std::make_shared<DensityField>(std::move(f));
}

// Simpson over [a, b] of D, n even.
double simpsonD(const DensityField& f, glm::dvec3 a, glm::dvec3 b, int n) {
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const glm::dvec3 x = a + (b - a) * (double(i) / n);
    sum += f.sample(glm::vec3(x)) * ((i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0));
  }
  return sum * glm::length(b - a) / n / 3.0;
}

// L_in of one unshadowed beam with the hazy phase, by Simpson over t with D(x) inside and each
// transmittance a Simpson integral of D of its own.
double quadratureLin(const BeamState& beam, const MediumState& m, glm::dvec3 e, glm::dvec3 v, double tEnd) {
  const int n = 6000;
  const double sigmaT = m.scattering + m.absorption;
  const glm::dvec3 lens(beam.pose.lensPosition), zb(beam.pose.zb);
  const DensityField& field = *m.density;
  const Distribution& d = *beam.optics.distribution;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double t = tEnd * i / n;
    const glm::dvec3 x = e + t * v;
    const double r = glm::length(x - lens);
    const glm::dvec3 wl = (x - lens) / r;
    const double theta = std::acos(std::clamp(glm::dot(wl, zb), -1.0, 1.0));
    const double intensity = d.intensityCd(float(theta), 0.0f);
    if (intensity <= 0.0) continue;
    const double c2 = 0.5 * (1.0 + glm::dot(wl, -v));
    const double phase = (1.0 + 9.0 * c2 * c2 * c2) / (13.0 * kPiD);
    const double path = simpsonD(field, lens, x, 400) + simpsonD(field, e, x, 400);
    const double fx = m.scattering * field.sample(glm::vec3(x)) * phase * intensity * std::exp(-sigmaT * path) / (r * r);
    sum += fx * ((i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0));
  }
  return sum * (tEnd / n) / 3.0;
}

TEST(ReferenceDensity, MatchesAnIndependentQuadratureThroughALumpyField) {
  struct Case {
    glm::vec3 eye, lookAt;
  };
  const Case cases[] = {
      {{-4.0f, 2.0f, 3.5f}, {1.0f, 2.4f, -1.0f}},   // across the beam through the lump
      {{-4.0f, 0.3f, 3.0f}, {3.0f, 0.4f, -2.0f}},   // along the fog layer under the beam
      {{0.3f, 1.5f, 0.2f}, {2.0f, 4.0f, -1.0f}},    // from inside the cone
  };
  Venue v = test::emptyVenue();
  const Bvh bvh(v);
  FrameState f;
  f.medium.scattering = 0.06f;
  f.medium.absorption = 0.02f;
  f.medium.phase = Phase::Hazy;
  f.medium.density = lumpyField();
  f.beams.push_back(test::makeBeam({0.5f, 6.0f, -0.2f}, {0.1f, -1.0f, 0.05f}, test::parametric(20, 35, 5000), 35));
  for (const Case& c : cases) {
    const glm::vec3 dir = glm::normalize(c.lookAt - c.eye);
    const PixelRadiance p = radianceAlongRay(bvh, f, c.eye, dir);
    const double tEnd = 12.0;  // past the cone: what lies beyond adds nothing
    f.camera.farM = static_cast<float>(tEnd);
    const PixelRadiance q = radianceAlongRay(bvh, f, c.eye, dir);
    const double expected = quadratureLin(f.beams[0], f.medium, glm::dvec3(c.eye), glm::dvec3(dir), tEnd);
    EXPECT_GT(expected, 0.0);
    EXPECT_NEAR(q.inScattered.r, expected, 0.005 * expected) << c.eye.x << "," << c.eye.y;
    EXPECT_NEAR(p.inScattered.r, q.inScattered.r, 1e-3 * expected);
    f.camera.farM = 100.0f;
  }
}

}  // namespace
}  // namespace haze
