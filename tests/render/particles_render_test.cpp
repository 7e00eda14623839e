// Visible dust (docs/rendering.md, "Particles"): off, the radiance is bit for bit the image
// without the option; on, light is added only where an eye ray crosses a beam's cone, the same at
// the same time, elsewhere at a later time, in proportion to the density, and none for a dark beam.
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "app/render_session.h"
#include "render_test_util.h"
#include "renderer/renderer.h"
#include "renderer/scene/camera_basis.h"

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

TEST_F(ParticlesRender, ADarkBeamShowsNone) {
  const Render off = renderFrame(venue_, dustFrame(false, 300.0f, 0.0, 0.0f));
  const Render on = renderFrame(venue_, dustFrame(true, 300.0f, 0.0, 0.0f));
  EXPECT_EQ(on.times.particlesDrawn, 0u);
  EXPECT_TRUE(std::equal(on.image.pixels.begin(), on.image.pixels.end(), off.image.pixels.begin()));
}

}  // namespace
}  // namespace haze::test
