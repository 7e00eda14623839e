// The reference's in-scattering L_in against independent answers: the closed form for a uniform
// beam crossed at right angles (sigma_s I / (4 pi) * 2 alpha / h), the same with a shadow edge,
// and a brute-force Simpson quadrature of docs/physics.md's integral written out here, for tilted
// beams, the hazy phase, extinction, a camera inside the cone and a floor that ends the ray.
// Then the convergence criterion of docs/physics.md on a scene with a sphere's shadow in the beam.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "renderer/reference/reference.h"
#include "shows/scene/physics.h"
#include "unit/scene/test_scenes.h"

namespace haze {
namespace {

using test::kPiD;

FrameState isotropicFrame(float sigmaS) {
  FrameState f;
  f.medium.scattering = sigmaS;
  f.medium.phase = Phase::Isotropic;
  return f;
}

// Along a ray crossing the axis at right angles at distance h from the lens, a uniform beam of
// I cd and half-angle alpha gives, with negligible extinction,
// L_in = sigma_s I / (4 pi) * integral over the chord of dt / (h^2 + t^2) = sigma_s I / (4 pi) * 2 alpha / h.
TEST(ReferenceVolume, UniformBeamCrossedAtRightAnglesMatchesTheClosedForm) {
  const float alphaDeg = 15.0f, cd = 1000.0f, sigma = 1e-6f;
  const Venue v = test::emptyVenue();
  const Bvh bvh(v);
  FrameState f = isotropicFrame(sigma);
  f.beams.push_back(test::makeBeam({0, 5, 0}, {0, -1, 0}, test::uniformDistribution(alphaDeg, cd),
                                   2 * alphaDeg));
  for (float h : {0.5f, 3.0f, 20.0f}) {
    const PixelRadiance p = radianceAlongRay(bvh, f, {-30, 5 - h, 0}, {1, 0, 0});
    const double alpha = alphaDeg * kPiD / 180.0;
    const double expected = sigma * cd / (4 * kPiD) * 2 * alpha / h;
    EXPECT_NEAR(p.inScattered.r, expected, 1e-3 * expected) << "h " << h;
    EXPECT_FALSE(p.hitSurface);
  }
}

TEST(ReferenceVolume, ShadowEdgeInTheBeamIsExact) {
  // A sheet 0.5 m under the lens covering x > c blocks the directions beyond
  // psi = atan(c / 0.5) on that side: the lit part of the chord is phi in [-alpha, psi].
  const float alphaDeg = 15.0f, cd = 1000.0f, sigma = 1e-6f, c = 0.05f, h = 3.0f;
  Venue v = test::emptyVenue();
  test::addQuad(v, {c, 4.5f, -5}, {c, 4.5f, 5}, {5, 4.5f, 5}, {5, 4.5f, -5});
  const Bvh bvh(v);
  FrameState f = isotropicFrame(sigma);
  f.beams.push_back(test::makeBeam({0, 5, 0}, {0, -1, 0}, test::uniformDistribution(alphaDeg, cd),
                                   2 * alphaDeg));
  const double alpha = alphaDeg * kPiD / 180.0, psi = std::atan(c / 0.5);
  const double expected = sigma * cd / (4 * kPiD) * (alpha + psi) / h;
  const PixelRadiance p = radianceAlongRay(bvh, f, {-30, 5 - h, 0}, {1, 0, 0});
  EXPECT_NEAR(p.inScattered.r, expected, 1e-3 * expected);
  // Without edge refinement the midpoint rule is still close, only less exact.
  ReferenceOptions plain;
  plain.refineShadowEdges = false;
  const PixelRadiance q = radianceAlongRay(bvh, f, {-30, 5 - h, 0}, {1, 0, 0}, plain);
  EXPECT_NEAR(q.inScattered.r, expected, 1e-2 * expected);
}

TEST(ReferenceVolume, StepInsideTheDistributionIsResolved) {
  // 1000 cd out to e degrees, then 250 cd out to 15. Along any ray in a plane through the axis,
  // theta = |phi - phi_axis| (phi the angle seen from the lens), so
  // L_in = sigma_s / (4 pi D) * 2 * integral_0^15deg I(theta) dtheta, D = the ray's distance to
  // the lens. e is chosen off the march's step grid, so only the edge refinement makes this exact.
  const float e = 8.037f;
  auto d = std::make_shared<Distribution>();
  d->gammaDeg = {0.0f, e, e + 0.001f, 15.0f};
  d->cDeg = {0.0f};
  d->candela = {1000.0f, 1000.0f, 250.0f, 250.0f};
  const Venue v = test::emptyVenue();
  const Bvh bvh(v);
  FrameState f = isotropicFrame(1e-6f);
  f.beams.push_back(test::makeBeam({0, 5, 0}, {0, -1, 0}, d, 30));
  const double deg = kPiD / 180.0;
  const double integral = deg * (1000.0 * e + 625.0 * 0.001 + 250.0 * (15.0 - e - 0.001));
  const glm::vec3 lens(0, 5, 0);
  for (glm::vec3 dir : {glm::vec3(1, 0, 0), glm::normalize(glm::vec3(1, -0.05f, 0))}) {
    const glm::vec3 eye(-30, 3, 0);
    const glm::vec3 toLens = lens - eye;
    const double dist = glm::length(toLens - glm::dot(toLens, dir) * dir);
    const double expected = 1e-6 * 2 * integral / (4 * kPiD * dist);
    const PixelRadiance p = radianceAlongRay(bvh, f, eye, dir);
    EXPECT_NEAR(p.inScattered.r, expected, 1e-3 * expected) << dir.y;
  }
}

// docs/physics.md's L_in for one unshadowed beam, by composite Simpson over t in [0, T] with the
// hazy phase written out: independent of the reference's cone chord and angular march.
double quadratureLin(const BeamState& beam, const MediumState& m, glm::dvec3 e, glm::dvec3 v,
                     double tEnd) {
  const int n = 100000;
  const double sigmaT = m.scattering + m.absorption;
  const glm::dvec3 lens(beam.pose.lensPosition);
  const glm::dvec3 zb(beam.pose.zb);
  const Distribution& d = *beam.optics.distribution;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double t = tEnd * i / n;
    const glm::dvec3 x = e + t * v;
    const double r = glm::length(x - lens);
    const glm::dvec3 wl = (x - lens) / r;
    const double theta = std::acos(std::clamp(glm::dot(wl, zb), -1.0, 1.0));
    const double cosA = glm::dot(wl, -v);
    const double c2 = 0.5 * (1.0 + cosA);
    const double phase = (1.0 + 9.0 * c2 * c2 * c2) / (13.0 * kPiD);
    const double f = m.scattering * phase * d.intensityCd(float(theta), 0.0f) *
                     std::exp(-sigmaT * r) / (r * r) * std::exp(-sigmaT * t);
    sum += f * ((i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0));
  }
  return sum * (tEnd / n) / 3.0;
}

struct QuadCase {
  glm::vec3 lens, axis, eye, lookAt;
  bool withFloor;
};

TEST(ReferenceVolume, MatchesAnIndependentQuadratureOfTheIntegral) {
  const QuadCase cases[] = {
      // Tilted beam, eye ray slanting through it down to the floor.
      {{0.3f, 6.0f, -0.2f}, {0.2f, -1.0f, 0.1f}, {-6.0f, 1.5f, 4.0f}, {1.0f, 0.0f, -1.0f}, true},
      // Same beam, ray that misses the floor and runs to far through the beam.
      {{0.3f, 6.0f, -0.2f}, {0.2f, -1.0f, 0.1f}, {-6.0f, 2.5f, 4.0f}, {3.0f, 3.0f, -3.0f}, false},
      // Camera inside the cone, looking sideways and down: the chord starts at the eye.
      {{0.0f, 6.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, {0.2f, 2.0f, 0.1f}, {3.0f, 1.1f, 0.7f}, true},
      // Camera inside the cone looking up past the lens into the back cone (1 m from the lens).
      {{0.0f, 6.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, {0.2f, 2.0f, 0.1f}, {1.0f, 6.0f, 0.0f}, false},
  };
  for (const QuadCase& qc : cases) {
    Venue v = test::emptyVenue();
    if (qc.withFloor) test::addFloor(v, 0.0f, 50.0f);
    const Bvh bvh(v);
    FrameState f;
    f.medium.scattering = 0.04f;
    f.medium.absorption = 0.01f;
    f.medium.phase = Phase::Hazy;
    f.beams.push_back(test::makeBeam(qc.lens, qc.axis, test::parametric(20, 35, 5000), 35));
    const glm::vec3 dir = glm::normalize(qc.lookAt - qc.eye);
    const PixelRadiance p = radianceAlongRay(bvh, f, qc.eye, dir);
    EXPECT_EQ(p.hitSurface, qc.withFloor);
    const double tEnd = qc.withFloor ? qc.eye.y / -double(dir.y) : f.camera.farM;
    EXPECT_NEAR(p.depthM, tEnd, 1e-4 * tEnd);
    const double expected = quadratureLin(f.beams[0], f.medium, glm::dvec3(qc.eye),
                                          glm::dvec3(dir), tEnd);
    EXPECT_GT(expected, 0.0);
    EXPECT_NEAR(p.inScattered.r, expected, 0.005 * expected)
        << "eye " << qc.eye.x << "," << qc.eye.y << "," << qc.eye.z;
  }
}

TEST(ReferenceVolume, ColourAndBeamsAddUp) {
  const Venue v = test::emptyVenue();
  const Bvh bvh(v);
  FrameState one = isotropicFrame(0.05f);
  one.beams.push_back(test::makeBeam({0, 5, 0}, {0, -1, 0}, test::parametric(10, 20, 800), 20,
                                     {1.0f, 0.5f, 0.0f}));
  FrameState two = one;
  two.beams.push_back(test::makeBeam({2, 5, 0}, {-0.3f, -1, 0}, test::parametric(15, 30, 500), 30));
  FrameState second = one;
  second.beams = {two.beams[1]};
  const glm::vec3 e(-6, 2, 3), d = glm::normalize(glm::vec3(1, 0.1f, -0.5f));
  const glm::vec3 a = radianceAlongRay(bvh, one, e, d).inScattered;
  const glm::vec3 b = radianceAlongRay(bvh, second, e, d).inScattered;
  const glm::vec3 ab = radianceAlongRay(bvh, two, e, d).inScattered;
  EXPECT_GT(a.r, 0.0f);
  EXPECT_GT(b.r, 0.0f);
  EXPECT_NEAR(a.g, 0.5f * a.r, 1e-6f * a.r);
  EXPECT_EQ(a.b, 0.0f);
  EXPECT_NEAR(ab.r, a.r + b.r, 1e-5f * ab.r);
}

TEST(ReferenceVolume, RayThroughTheLensStaysFinite) {
  const Venue v = test::emptyVenue();
  const Bvh bvh(v);
  FrameState f = isotropicFrame(0.05f);
  f.beams.push_back(test::makeBeam({0, 5, 0}, {0, -1, 0}, test::parametric(10, 20, 800), 20));
  for (glm::vec3 e : {glm::vec3(0, 8, 0), glm::vec3(0, 5, 0)}) {
    const glm::vec3 l = radianceAlongRay(bvh, f, e, {0, -1, 0}).total();
    EXPECT_TRUE(std::isfinite(l.r) && l.r > 0.0f);
  }
}

// A small hazy scene with a sphere's shadow in a beam, a second beam grazing the sphere, a floor.
FrameState convergenceScene(Venue& v, bool withSphere = true) {
  v = test::emptyVenue();
  const int grey = test::addMaterial(v, glm::vec3(0.5f));
  test::addFloor(v, 0.0f, 10.0f, grey);
  if (withSphere) test::addUvSphere(v, {0, 2.8f, 0}, 0.35f, 12, 24, grey);
  FrameState f;
  f.camera.position = {0.5f, 2.0f, 7.0f};
  f.camera.target = {0, 2.0f, 0};
  f.camera.fovYDeg = 55.0f;
  f.medium.scattering = 0.05f;
  f.medium.absorption = 0.01f;
  f.beams.push_back(test::makeBeam({0, 5, 0}, {0, -1, 0}, test::parametric(15, 25, 20000), 25));
  f.beams.push_back(test::makeBeam({-3, 4.5f, -1}, {0.8f, -0.5f, 0.3f},
                                   test::parametric(8, 14, 40000), 14, {0.2f, 0.6f, 1.0f}));
  return f;
}

TEST(ReferenceVolume, HalvingTheStepChangesNoPixelByMoreThanHalfAPercent) {
  Venue v;
  const FrameState f = convergenceScene(v);
  const Bvh bvh(v);
  const int w = 32, h = 24;
  const ReferenceOptions base;
  ReferenceOptions fine = base;
  fine.maxStepAngleRad = base.maxStepAngleRad / 2;
  fine.minStepsPerChord = base.minStepsPerChord * 2;
  const ReferenceImages a = renderReferenceImages(bvh, f, w, h, base);
  const ReferenceImages b = renderReferenceImages(bvh, f, w, h, fine);
  float maxIn = 0.0f, worst = 0.0f;
  int shadowed = 0;
  for (size_t k = 0; k < a.total.pixels.size(); ++k) {
    maxIn = std::max(maxIn, a.inScattered.pixels[k].r);
    for (int c = 0; c < 3; ++c) {
      const float x = a.total.pixels[k][c], y = b.total.pixels[k][c];
      // Relative, with a floor far below anything visible (1e-6 of the peak in-scatter).
      const float rel = std::fabs(x - y) / std::max(std::max(x, y), 1e-6f * maxIn + 1e-12f);
      worst = std::max(worst, rel);
    }
  }
  EXPECT_LT(worst, 0.005f);
  // The scene is what it claims: the sphere's shadow darkens part of the beams (against the
  // same scene without the sphere).
  EXPECT_GT(maxIn, 0.0f);
  Venue open;
  const FrameState fOpen = convergenceScene(open, false);
  const Bvh bvhOpen(open);
  const ReferenceImages c = renderReferenceImages(bvhOpen, fOpen, w, h, base);
  for (size_t k = 0; k < a.total.pixels.size(); ++k) {
    const float lit = c.inScattered.pixels[k].r;
    if (lit > 0.01f * maxIn && a.inScattered.pixels[k].r < 0.5f * lit) ++shadowed;
  }
  EXPECT_GT(shadowed, 5);
  std::printf("convergence: worst relative change %.5f over %d pixels, %d in the shadow\n", worst,
              w * h, shadowed);
}

TEST(ReferenceVolume, ThreadCountDoesNotChangeTheImage) {
  Venue v;
  const FrameState f = convergenceScene(v);
  const Bvh bvh(v);
  ReferenceOptions one, three;
  one.threads = 1;
  three.threads = 3;
  const ReferenceImages a = renderReferenceImages(bvh, f, 16, 12, one);
  const ReferenceImages b = renderReferenceImages(bvh, f, 16, 12, three);
  EXPECT_EQ(a.total.pixels, b.total.pixels);
  // The single-pixel entry point gives the image's own values.
  for (int j : {0, 5, 11})
    for (int i : {0, 7, 15})
      EXPECT_EQ(radianceAtPixel(bvh, f, 16, 12, i, j).total(), a.total.at(i, j)) << i << "," << j;
  for (size_t k = 0; k < a.total.pixels.size(); ++k) {
    const glm::vec3 sum = a.surface.pixels[k] + a.inScattered.pixels[k];
    EXPECT_NEAR(glm::length(a.total.pixels[k] - sum), 0.0f, 1e-6f * glm::length(sum) + 1e-12f);
  }
}

}  // namespace
}  // namespace haze
