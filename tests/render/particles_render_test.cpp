// Visible dust (docs/rendering.md, "Particles"): off, the radiance is bit for bit the image
// without the option; on, light is added only where an eye ray crosses a beam's cone, the same at
// the same time, elsewhere at a later time, in proportion to the density, and none for a dark beam;
// above the frame's limit the render warns with the numbers.
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "app/render_session.h"
#include "render_test_util.h"
#include "renderer/renderer.h"
#include "shows/scene/camera_basis.h"
#include "shows/scene/physics.h"

namespace haze::test {
namespace {

constexpr int kW = 320, kH = 180;
const glm::vec3 kLens{0.0f, 5.0f, 0.0f};
const glm::vec3 kDir = glm::normalize(glm::vec3(0.3f, -1.0f, 0.0f));
constexpr float kFieldDeg = 24.0f;

FrameState dustFrame(bool enabled, float density = 300.0f, double timeS = 0.0, float dimmer = 1.0f) {
  FrameState f;
  f.camera.position = {0.0f, 2.5f, 9.0f};
  f.camera.target = {0.5f, 2.5f, 0.0f};
  f.camera.fovYDeg = 45.0f;
  f.medium.scattering = 0.03f;
  f.beams.push_back(makeBeam(kLens, kDir, 16.0f, kFieldDeg, 40000.0f));
  f.beams[0].optics.dimmer *= dimmer;
  f.particles.settings.enabled = enabled;
  f.particles.settings.densityPerM3 = density;
  f.particles.timeS = timeS;
  f.particles.airFlowMps = {0.2f, 0.0f, 0.0f};
  return f;
}

struct Render {
  ImageRGB image;
  PassTimes times;
};

Render renderFrame(const Venue& venue, const FrameState& f) {
  auto r = Renderer::create(venue, renderSettingsFor(Quality::Draft, kW, kH));
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
  if (!r.ok()) return {};
  (*r)->render(f);
  return {(*r)->readRadiance(), (*r)->lastTimes()};
}

// on - off per pixel (luminance-like sum of channels).
std::vector<float> added(const ImageRGB& on, const ImageRGB& off) {
  std::vector<float> d(on.pixels.size());
  for (size_t i = 0; i < d.size(); ++i) {
    const glm::vec3 v = on.pixels[i] - off.pixels[i];
    d[i] = v.r + v.g + v.b;
  }
  return d;
}

// Pixels whose eye ray crosses the cone before the floor (y = 0), dilated by 2 pixels for the
// particles' kernel (radius 1.5 px).
std::vector<char> coneMask(const FrameState& f, float cutoffRad) {
  const CameraBasis b = cameraBasis(f.camera, float(kW) / kH);
  std::vector<char> hit(static_cast<size_t>(kW) * kH, 0);
  const float cosC = std::cos(cutoffRad);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const float sx = ((x + 0.5f) / kW) * 2.0f - 1.0f, sy = 1.0f - ((y + 0.5f) / kH) * 2.0f;
      const glm::vec3 ray = glm::normalize(b.forward + sx * b.tanX * b.right + sy * b.tanY * b.up);
      for (float t = 0.05f; t < 30.0f; t += 0.01f) {
        const glm::vec3 p = f.camera.position + t * ray;
        if (p.y < 0.0f) break;
        const glm::vec3 d = p - kLens;
        if (glm::dot(d, kDir) > cosC * glm::length(d)) {
          hit[static_cast<size_t>(y) * kW + x] = 1;
          break;
        }
      }
    }
  std::vector<char> out(hit.size(), 0);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u >= 0 && v >= 0 && u < kW && v < kH && hit[static_cast<size_t>(v) * kW + u])
            out[static_cast<size_t>(y) * kW + x] = 1;
        }
  return out;
}

class ParticlesRender : public GlTest {
 protected:
  Venue venue_ = floorVenue(20.0f, 0.3f);
};

TEST_F(ParticlesRender, OffIsBitIdenticalToTheRadiometricImage) {
  const Render plain = renderFrame(venue_, [] {
    FrameState f = dustFrame(false);
    f.particles = ParticleState{};  // never touched: the frame every renderer drew before particles
    return f;
  }());
  const Render off = renderFrame(venue_, dustFrame(false, 4000.0f, 30.0));
  ASSERT_EQ(plain.image.pixels.size(), off.image.pixels.size());
  EXPECT_TRUE(std::equal(plain.image.pixels.begin(), plain.image.pixels.end(), off.image.pixels.begin()));
  EXPECT_EQ(off.times.particlesDrawn, 0u);
}

TEST_F(ParticlesRender, LightIsAddedOnlyInsideTheBeam) {
  const FrameState f = dustFrame(true);
  const Render on = renderFrame(venue_, f), off = renderFrame(venue_, dustFrame(false));
  const std::vector<float> d = added(on.image, off.image);
  const std::vector<char> mask = coneMask(f, f.beams[0].optics.cutoffHalfAngleRad());
  int inside = 0, outside = 0;
  double light = 0;
  for (size_t i = 0; i < d.size(); ++i) {
    EXPECT_GE(d[i], -1e-6f) << "pixel " << i;  // light is only added
    if (d[i] <= 0.0f) continue;
    light += d[i];
    (mask[i] ? inside : outside) += 1;
  }
  std::printf("  %zu particles drawn, %d pixels lit inside the cone, %d outside\n", on.times.particlesDrawn, inside,
              outside);
  EXPECT_GT(on.times.particlesDrawn, 500u);
  EXPECT_GT(inside, 1000);
  EXPECT_EQ(outside, 0);
  EXPECT_GT(light, 0.0);
}

// The light the particles add, summed over the image as L times each pixel's solid angle, is the
// flux physics.md gives them at the eye: sum of G C p(a) I_eff / r^2 T T / d^2 over the same
// particles (found again on the CPU: the cone out to the floor, the box the renderer uses).
TEST_F(ParticlesRender, AddedLightIsTheParticlesFluxAtTheEye) {
  const FrameState f = dustFrame(true, 100.0f, 1.0);
  const Render on = renderFrame(venue_, f), off = renderFrame(venue_, dustFrame(false));
  const CameraBasis b = cameraBasis(f.camera, float(kW) / kH);
  const double pixelSr = 4.0 * b.tanX * b.tanY / (double(kW) * kH);
  double measured = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const float sx = ((x + 0.5f) / kW) * 2.0f - 1.0f, sy = 1.0f - ((y + 0.5f) / kH) * 2.0f;
      const glm::vec3 ray = b.forward + sx * b.tanX * b.right + sy * b.tanY * b.up;
      const double cosT = 1.0 / glm::length(ray);
      const size_t i = static_cast<size_t>(y) * kW + x;
      measured += (on.image.pixels[i].r - off.image.pixels[i].r) * pixelSr * cosT * cosT * cosT;
    }
  const BeamState& beam = f.beams[0];
  const std::vector<ParticleCone> cones = {
      {.apex = kLens, .axis = kDir, .halfAngleRad = beam.optics.cutoffHalfAngleRad(), .lengthM = 30.0f, .beam = 0}};
  const glm::vec3 lo = glm::min(venue_.boundsMin, f.camera.position), hi = glm::max(venue_.boundsMax, kLens);
  const ParticleSet set = generateParticles(f.particles, cones, nullptr, glm::min(lo, kLens),
                                            glm::max(hi, f.camera.position));
  const float sigmaT = f.medium.extinction();
  double expected = 0;
  for (const Particle& p : set.particles) {
    const glm::vec3 toLens = p.positionM - kLens, toEye = f.camera.position - p.positionM;
    const float r = glm::length(toLens), d = glm::length(toEye);
    const float cosA = glm::dot(toLens / r, toEye / d);
    const double J = f.particles.settings.brightness * p.crossSectionM2 * phaseFunction(f.medium, cosA) *
                     beamIntensityTowards(beam, p.positionM).r / (r * r) * std::exp(-sigmaT * r);
    expected += J * std::exp(-sigmaT * d) / (d * d);
  }
  std::printf("  %zu particles on the GPU, %zu on the CPU; flux at the eye %.6g, expected %.6g (%.2f %%)\n",
              on.times.particlesDrawn, set.particles.size(), measured, expected, 100.0 * (measured / expected - 1.0));
  EXPECT_EQ(on.times.particlesDrawn, set.particles.size());
  EXPECT_NEAR(measured / expected, 1.0, 0.01);  // measured 0.1 %: ten times that
}

TEST_F(ParticlesRender, TheSameTimeGivesTheSameImageALaterTimeMovesThem) {
  const Render a = renderFrame(venue_, dustFrame(true, 40.0f, 4.0));
  const Render b = renderFrame(venue_, dustFrame(true, 40.0f, 4.0));
  EXPECT_TRUE(std::equal(a.image.pixels.begin(), a.image.pixels.end(), b.image.pixels.begin()));
  const Render off = renderFrame(venue_, dustFrame(false));
  const Render later = renderFrame(venue_, dustFrame(true, 40.0f, 6.0));
  const std::vector<float> da = added(a.image, off.image), dl = added(later.image, off.image);
  // Sparse dust (40 per m^3): the pixels of the earlier particles, dark once they have moved on.
  int litA = 0, movedAway = 0;
  for (size_t i = 0; i < da.size(); ++i) {
    if (da[i] <= 0.0f) continue;
    ++litA;
    if (dl[i] <= 0.0f) ++movedAway;
  }
  std::printf("  %d pixels lit at 4 s, %d of them dark at 6 s\n", litA, movedAway);
  ASSERT_GT(litA, 1000);
  EXPECT_GT(movedAway, litA / 4);
}

TEST_F(ParticlesRender, CountAndLightFollowTheDensity) {
  const Render off = renderFrame(venue_, dustFrame(false));
  const Render thin = renderFrame(venue_, dustFrame(true, 100.0f)), thick = renderFrame(venue_, dustFrame(true, 400.0f));
  const double count = double(thick.times.particlesDrawn) / double(thin.times.particlesDrawn);
  double lThin = 0, lThick = 0;
  for (float v : added(thin.image, off.image)) lThin += v;
  for (float v : added(thick.image, off.image)) lThick += v;
  std::printf("  %zu and %zu particles (x %.2f), light x %.2f\n", thin.times.particlesDrawn,
              thick.times.particlesDrawn, count, lThick / lThin);
  EXPECT_NEAR(count, 4.0, 0.4);
  EXPECT_NEAR(lThick / lThin, 4.0, 0.8);
}

TEST_F(ParticlesRender, AboveTheLimitTheRenderSaysHowManyWereLeftOut) {
  FrameState f = dustFrame(true);
  f.particles.limit = 100;
  auto r = Renderer::create(venue_, renderSettingsFor(Quality::Draft, kW, kH));
  ASSERT_TRUE(r.ok()) << r.error().str();
  (*r)->render(f);
  const PassTimes& t = (*r)->lastTimes();
  EXPECT_EQ(t.particlesDrawn, 100u);
  EXPECT_GT(t.particlesWanted, 1000u);
  ASSERT_EQ((*r)->warnings().size(), 1u);
  EXPECT_EQ((*r)->warnings()[0], "particles: 100 of " + std::to_string(t.particlesWanted) +
                                     " drawn, the limit of 100 per frame (thinned evenly; lower the particle density)");
  f.particles.limit = kDefaultParticleLimit;
  (*r)->render(f);
  EXPECT_TRUE((*r)->warnings().empty());
}

TEST_F(ParticlesRender, ADarkBeamShowsNone) {
  const Render off = renderFrame(venue_, dustFrame(false, 300.0f, 0.0, 0.0f));
  const Render on = renderFrame(venue_, dustFrame(true, 300.0f, 0.0, 0.0f));
  EXPECT_EQ(on.times.particlesDrawn, 0u);
  EXPECT_TRUE(std::equal(on.image.pixels.begin(), on.image.pixels.end(), off.image.pixels.begin()));
}

}  // namespace
}  // namespace haze::test
