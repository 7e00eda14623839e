// Static features (renderer/shader_features.h, shaders/interface.h): the planes' and surfaces'
// programs with the frame's density field, sun, soft shadows and phase function compiled in
// must give the image the programs that read them from uniforms give, value for value (to
// float rounding), for frames that have each of them and frames that have none. A variant that
// compiled a switch out while the frame has it (a sun left dark, a field read as uniform haze)
// fails here. The test also checks that the variants were built and used: a comparison of the
// uniform programs with themselves would pass and prove nothing.
#include <algorithm>
#include <cmath>

#include "app/bench_scene.h"
#include "atmosphere/density_sim.h"
#include "render_test_util.h"
#include "renderer/gl/program.h"
#include "renderer/renderer.h"

namespace haze::test {
namespace {

class StaticFeatures : public GlTest {};

struct Rendered {
  ImageRGB image;
  uint64_t programsBuilt = 0;  // while rendering: the static variants built on first use
};

Rendered render(const Venue& venue, const FrameState& frame, bool staticFeatures) {
  RenderSettings s{.width = 320, .height = 180, .shadowMapSize = 512, .planes = 24, .scatterDivisor = 2,
                   .refineCurvature = 0.1f, .refineFloor = 2.0f};
  s.staticFeatures = staticFeatures;
  auto r = Renderer::create(venue, s);
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
  if (!r.ok()) return {};
  const uint64_t before = gl::programBuildCount();
  (*r)->render(frame);
  return {(*r)->readRadiance(), gl::programBuildCount() - before};
}

struct Case {
  const char* name;
  bool soft, field, sun;
  Phase phase;
};

void expectSameImage(const Case& c) {
  SCOPED_TRACE(c.name);
  const Venue venue = benchVenue(16);
  FrameState frame = benchFrame(16);
  frame.softShadows = c.soft;
  frame.medium.phase = c.phase;
  frame.medium.g = 0.4f;
  if (c.field) {
    DensitySpec spec = benchDensity(16);
    DensitySim sim(spec, densityGrid(spec, venue.boundsMin, venue.boundsMax));
    frame.medium.density = std::make_shared<DensityField>(sim.fieldAt(20.0));
  }
  if (c.sun) {
    frame.sun.on = true;
    frame.sun.direction = glm::normalize(glm::vec3(0.5f, -0.6f, -0.6f));
    frame.sun.illuminance = glm::vec3(20000.0f);
  }
  const Rendered uniforms = render(venue, frame, false);
  const Rendered compiled = render(venue, frame, true);
  EXPECT_EQ(uniforms.programsBuilt, 0u);
  EXPECT_GE(compiled.programsBuilt, 2u);  // the planes' and the surfaces' variants (and the refinement's)
  ASSERT_EQ(uniforms.image.pixels.size(), compiled.image.pixels.size());
  ASSERT_FALSE(uniforms.image.pixels.empty());
  float maxL = 0.0f, maxDiff = 0.0f;
  for (size_t i = 0; i < uniforms.image.pixels.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      maxL = std::max(maxL, uniforms.image.pixels[i][k]);
      maxDiff = std::max(maxDiff, std::abs(uniforms.image.pixels[i][k] - compiled.image.pixels[i][k]));
    }
  ASSERT_GT(maxL, 1.0f);  // lit, so a feature compiled out could not hide
  EXPECT_LE(maxDiff, 1e-5f * maxL) << "largest difference " << maxDiff << " of " << maxL;
}

TEST_F(StaticFeatures, SoftShadowsOnly) { expectSameImage({"soft shadows, hazy", true, false, false, Phase::Hazy}); }
TEST_F(StaticFeatures, HardShadowsFieldSunHenyeyGreenstein) {
  expectSameImage({"hard shadows, density field, sun, Henyey-Greenstein", false, true, true, Phase::HenyeyGreenstein});
}
TEST_F(StaticFeatures, SoftShadowsFieldIsotropic) {
  expectSameImage({"soft shadows, density field, isotropic", true, true, false, Phase::Isotropic});
}
TEST_F(StaticFeatures, HardShadowsSun) { expectSameImage({"hard shadows, sun, hazy", false, false, true, Phase::Hazy}); }

}  // namespace
}  // namespace haze::test
