// The GL renderer with a density field (docs/rendering.md, "Density"): a field of ones changes
// no image (so no existing render test's result can change), and a beam through a hazer's plume
// and a beam across a ground-fog layer against the CPU reference on L_in (compareBeams), at
// high and default, and the surfaces seen and lit through the field. Limits: the measured errors
// times 1.5 (rounded up), printed with them; each is checked to fail a 10 % error and the uniform medium.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "app/render_session.h"
#include "atmosphere/density_sim.h"
#include "render_test_util.h"
#include "renderer/reference/reference.h"
#include "renderer/renderer.h"
#include "shows/scene/bvh.h"
#include "shows/scene/image_compare.h"

namespace haze::test {
namespace {

constexpr int kW = 240, kH = 180;

// A stage: floor, a sphere, a spot from above and a second beam slanting across.
FrameState stage(Venue& venue) {
  venue = floorVenue(16.0f, 0.5f);
  addSphere(venue, {0.4f, 2.2f, 0.0f}, 0.4f);
  addBox(venue, {-8, 0, -8.2f}, {8, 6, -8});  // a back wall, so the boundsreach 6 m up
  FrameState f;
  f.camera.position = {0.0f, 2.2f, 8.0f};
  f.camera.target = {0.0f, 1.6f, 0.0f};
  f.camera.fovYDeg = 50.0f;
  f.medium.scattering = 0.05f;
  f.medium.absorption = 0.01f;
  f.medium.ambient = glm::vec3(0.02f);
  f.medium.background = glm::vec3(0.5f);
  f.beams.push_back(makeBeam({0.0f, 5.0f, 0.0f}, {0.05f, -1.0f, 0.0f}, 16, 26, 30000));
  f.beams.push_back(makeBeam({-4.0f, 4.5f, -1.0f}, {0.8f, -0.55f, 0.2f}, 8, 14, 40000, {0.3f, 0.6f, 1.0f}));
  f.beams[1].poseKey = 2;
  return f;
}

ImageRGB renderWith(const Venue& venue, const FrameState& frame, Quality q) {
  auto r = Renderer::create(venue, renderSettingsFor(q, kW, kH));
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
  if (!r.ok()) return {};
  (*r)->render(frame);
  return (*r)->readRadiance();
}

class DensityRender : public GlTest {};

TEST_F(DensityRender, AFieldOfOnesChangesNoImage) {
  Venue venue;
  FrameState frame = stage(venue);
  for (Quality q : {Quality::Default, Quality::High, Quality::Draft}) {
    const ImageRGB uniform = renderWith(venue, frame, q);
    FrameState ones = frame;
    ones.medium.density = std::make_shared<DensityField>(
        DensityField::filled(32, 16, 32, venue.boundsMin, venue.boundsMax, 1.0f));
    const ImageRGB withField = renderWith(venue, ones, q);
    ASSERT_EQ(uniform.pixels.size(), withField.pixels.size());
    float peak = 0.0f, worst = 0.0f;
    for (const glm::vec3& p : uniform.pixels) peak = std::max({peak, p.r, p.g, p.b});
    for (size_t i = 0; i < uniform.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        const float a = uniform.pixels[i][c], b = withField.pixels[i][c];
        worst = std::max(worst, std::fabs(a - b) / std::max(a, 1e-4f * peak));
      }
    std::printf("[ ones_%d ] worst relative difference %.2e\n", static_cast<int>(q), worst);
    EXPECT_LT(worst, 1e-5f);  // measured 7e-7: float rounding of the path sums
  }
}

// compareBeams on L_in against the reference; prints the numbers and checks the limits and
// that they would see a 10 % error.
void compareToReference(const std::string& name, const Venue& venue, const FrameState& frame, const ReferenceImages& ref,
                        Quality q, double coreLimit, double wideLimit, double surfaceLimit) {
  auto r = Renderer::create(venue, renderSettingsFor(q, kW, kH));
  ASSERT_TRUE(r.ok()) << r.error().str();
  FrameState dry = frame;
  dry.medium.absorption = frame.medium.extinction();
  dry.medium.scattering = 0.0f;
  (*r)->render(dry);
  ImageRGB gpu = (*r)->readRadiance();
  (*r)->render(frame);
  const ImageRGB wet = (*r)->readRadiance();
  // The surfaces through the field (lit through the lens's path, seen through the eye's): the
  // dry image against the reference's surface part, over the pixels above 1 % of its largest.
  {
    float peak = 0.0f;
    for (const glm::vec3& p : ref.surface.pixels) peak = std::max(peak, p.r);
    double sum = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < gpu.pixels.size(); ++i)
      if (ref.surface.pixels[i].r > 0.01f * peak) {
        sum += std::fabs(gpu.pixels[i].r - ref.surface.pixels[i].r) / ref.surface.pixels[i].r;
        ++count;
      }
    std::printf("[ %s ] surfaces: mean relative error %.4f over %zu pixels\n", name.c_str(), sum / count, count);
    EXPECT_GT(count, 500u);
    EXPECT_LT(sum / count, surfaceLimit) << name << " (surfaces)";
  }
  for (size_t i = 0; i < gpu.pixels.size(); ++i) gpu.pixels[i] = wet.pixels[i] - gpu.pixels[i];
  const auto c = compareBeams(gpu, ref.inScattered);
  ASSERT_TRUE(c.ok()) << c.error().str();
  std::printf("[ %s ] mean relative error %.4f over %zu core values, %.4f over %zu wide values; leak %.5f; gross %.5f\n",
              name.c_str(), c->coreError, c->coreValues, c->wideError, c->wideValues, c->leak(), c->gross());
  EXPECT_GE(c->coreValues, 40u);
  EXPECT_GE(c->wideValues, 200u);
  EXPECT_LT(c->coreError, coreLimit) << name;
  EXPECT_LT(c->wideError, wideLimit) << name;
  // And they see the density: the same frame in the uniform medium fails them.
  FrameState uniform = frame, uniformDry = dry;
  uniform.medium.density.reset();
  uniformDry.medium.density.reset();
  (*r)->render(uniformDry);
  ImageRGB flat = (*r)->readRadiance();
  (*r)->render(uniform);
  const ImageRGB flatWet = (*r)->readRadiance();
  for (size_t i = 0; i < flat.pixels.size(); ++i) flat.pixels[i] = flatWet.pixels[i] - flat.pixels[i];
  const auto u = compareBeams(flat, ref.inScattered);
  ASSERT_TRUE(u.ok());
  std::printf("[ %s ] the uniform medium instead: %.4f / %.4f\n", name.c_str(), u->coreError, u->wideError);
  EXPECT_FALSE(u->coreError < coreLimit && u->wideError < wideLimit) << name << ": the limits pass the uniform medium";
  ImageRGB brighter = gpu;
  for (glm::vec3& p : brighter.pixels) p *= 1.1f;
  const auto b = compareBeams(brighter, ref.inScattered);
  ASSERT_TRUE(b.ok());
  EXPECT_FALSE(b->coreError < coreLimit && b->wideError < wideLimit) << name << ": the limits pass a 10 % error";
  if (std::getenv("HAZE_TEST_IMAGES") || c->coreError >= coreLimit || c->wideError >= wideLimit)
    for (const auto& file : writeDiagnostics(name, gpu, ref.inScattered)) std::printf("[ %s ] wrote %s\n", name.c_str(), file.c_str());
}

TEST_F(DensityRender, ABeamThroughAHazerPlumeMatchesTheReference) {
  Venue venue;
  FrameState frame = stage(venue);
  frame.beams.pop_back();
  DensitySpec spec;
  spec.base = 0.2f;
  spec.airFlowMps = {0.05f, 0.02f, 0.0f};
  spec.hazers.push_back({.positionM = {-3.5f, 1.0f, 0.0f}, .direction = {1.0f, 0.25f, 0.0f}, .output = 2.0f,
                         .spreadDeg = 25.0f, .speedMps = 2.0f});
  spec.grid[0] = spec.grid[1] = spec.grid[2] = 32;
  DensitySim sim(spec, densityGrid(spec, venue.boundsMin, venue.boundsMax));
  frame.medium.density = std::make_shared<DensityField>(sim.fieldAt(20.0));
  // The plume is what it claims: thick where the beam crosses it.
  EXPECT_GT(frame.medium.density->sample({0.0f, 2.0f, 0.0f}), 1.0f);
  const Bvh bvh(venue);
  const ReferenceImages ref = renderReferenceImages(bvh, frame, kW, kH);
  // Measured (cores / wide / surfaces): high 0.23 % / 0.32 % / 0.06 %, default 1.54 % / 2.32 % / 0.09 %.
  compareToReference("plume_high", venue, frame, ref, Quality::High, 0.0035, 0.005, 0.001);
  compareToReference("plume_default", venue, frame, ref, Quality::Default, 0.024, 0.035, 0.0015);
}

TEST_F(DensityRender, ABeamAcrossGroundFogMatchesTheReference) {
  Venue venue;
  FrameState frame = stage(venue);
  frame.beams.erase(frame.beams.begin());
  DensitySpec spec;
  spec.base = 0.3f;
  spec.fog = FogLayerSpec{.density = 4.0f, .heightM = 0.4f, .falloffM = 0.3f};
  spec.grid[0] = 32;
  spec.grid[1] = 48;
  spec.grid[2] = 32;
  DensitySim sim(spec, densityGrid(spec, venue.boundsMin, venue.boundsMax));
  frame.medium.density = std::make_shared<DensityField>(sim.fieldAt(0.0));
  frame.camera.position = {1.0f, 1.2f, 7.0f};
  frame.camera.target = {0.5f, 0.6f, 0.0f};
  const Bvh bvh(venue);
  const ReferenceImages ref = renderReferenceImages(bvh, frame, kW, kH);
  // Measured (cores / wide / surfaces): high 0.19 % / 0.33 % / 0.66 %, default 0.78 % / 1.88 % / 0.64 %.
  compareToReference("fog_high", venue, frame, ref, Quality::High, 0.003, 0.005, 0.01);
  compareToReference("fog_default", venue, frame, ref, Quality::Default, 0.012, 0.029, 0.01);
}

}  // namespace
}  // namespace haze::test
