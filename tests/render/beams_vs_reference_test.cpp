// The GPU renderer (virtual planes on llvmpipe) against the CPU reference on radiometric images,
// over the pixels where L is above 1 % of the image maximum (docs/physics.md, "Accuracy").
// Tolerances: mean relative error at most 3 % at `high` and 8 % at `default` (issue 5). The
// remaining error is the planes' sampling noise, the light-map and shadow-map resolution, and
// rasterised (not traced) silhouettes; failing runs write actual/expected/diff PFMs into the
// build tree's test-output/ and print where.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include <glm/geometric.hpp>

#include "app/render_session.h"
#include "render_test_util.h"
#include "renderer/reference/reference.h"
#include "renderer/renderer.h"
#include "renderer/scene/image_compare.h"

namespace haze::test {
namespace {

// Images at 320x240, where every preset scatters at full resolution; the default preset's half
// resolution scattering at HD is tested on the hardest scene (the gobo) in GoboSpotFromTheSideHd.
constexpr int kWidth = 320, kHeight = 240;

class BeamsVsReference : public GlTest {
 protected:
  // The reference image of a scene, made once per test for both presets.
  const ImageRGB& reference(const Venue& venue, const FrameState& frame, int width, int height) {
    if (ref_.width != width || ref_.height != height) ref_ = renderReference(venue, frame, width, height);
    return ref_;
  }
  // Renders, compares, and fails the test when the mean relative error is not below
  // tolerance; only then (or with HAZE_TEST_IMAGES set) are the PFMs written, so passing runs
  // leave nothing behind.
  void run(const std::string& name, const Venue& venue, const FrameState& frame, RenderSettings settings,
           double tolerance) {
    auto r = Renderer::create(venue, settings);
    ASSERT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
    (*r)->render(frame);
    const ImageRGB gpu = (*r)->readRadiance();
    const ImageRGB& ref = reference(venue, frame, settings.width, settings.height);
    const auto c = compareImages(gpu, ref);
    bool passed = c.ok();
    if (c) {
      std::printf("[ %s ] planes %d, divisor %d, frames %d: mean relative error %.4f over %zu values "
                  "(max %.3f)\n", name.c_str(), settings.planes, settings.scatterDivisor, settings.frames,
                  c->meanRelError, c->values, c->maxRelError);
      EXPECT_LT(c->meanRelError, tolerance) << name;
      passed = c->meanRelError < tolerance;
    } else {
      ADD_FAILURE() << name << ": " << c.error().str();
    }
    if (!passed || std::getenv("HAZE_TEST_IMAGES"))
      for (const auto& file : writeDiagnostics(name, gpu, ref))
        std::printf("[ %s ] wrote %s\n", name.c_str(), file.c_str());
  }
  ImageRGB ref_;
};

// The presets of `haze render --quality` (app/render_session.cpp), as users get them.
RenderSettings high(int w, int h) { return renderSettingsFor(Quality::High, w, h); }
RenderSettings standard(int w, int h) { return renderSettingsFor(Quality::Default, w, h); }

// One spot in haze with a sphere in its beam: the shadow shaft below the sphere.
TEST_F(BeamsVsReference, SpotWithSphereShadowShaft) {
  Venue venue = floorVenue(16.0f, 0.4f);
  addSphere(venue, {0.0f, 3.0f, 0.0f}, 0.5f);
  FrameState frame;
  frame.camera.position = {0.0f, 3.0f, 10.0f};
  frame.camera.target = {0.0f, 2.5f, 0.0f};
  frame.camera.fovYDeg = 45.0f;
  frame.medium.scattering = 0.05f;
  frame.beams.push_back(makeBeam({0.0f, 7.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 20.0f, 30.0f, 50000.0f));
  run("sphere_shaft_high", venue, frame, high(kWidth, kHeight), 0.03);
  run("sphere_shaft_default", venue, frame, standard(kWidth, kHeight), 0.08);
}

// A procedural gobo: concentric rings and a bar, so the pattern has both curves and straight
// edges (white passes, black blocks).
std::shared_ptr<GoboImage> ringsGobo() {
  auto g = std::make_shared<GoboImage>();
  g->name = "rings";
  g->width = g->height = 256;
  g->transmittance.resize(256 * 256);
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      const float u = (x + 0.5f) / 128.0f - 1.0f, v = (y + 0.5f) / 128.0f - 1.0f;
      const float rr = std::sqrt(u * u + v * v);
      const bool ring = std::fmod(rr * 4.0f, 1.0f) < 0.5f;
      const bool bar = std::abs(u) < 0.08f;
      g->transmittance[static_cast<size_t>(y) * 256 + x] = (ring && !bar) ? 1.0f : 0.0f;
    }
  return g;
}

// A gobo'd spot seen from the side: the pattern in the beam and on the floor.
FrameState goboSideFrame() {
  FrameState frame;
  frame.camera.position = {9.0f, 2.5f, 0.0f};
  frame.camera.target = {0.0f, 2.0f, 0.0f};
  frame.camera.fovYDeg = 50.0f;
  frame.medium.scattering = 0.05f;
  BeamState b = makeBeam({0.0f, 6.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 18.0f, 26.0f, 60000.0f);
  b.optics.gobo = ringsGobo();
  b.optics.goboRotationDeg = 20.0f;
  frame.beams.push_back(b);
  return frame;
}

TEST_F(BeamsVsReference, GoboSpotFromTheSide) {
  const Venue venue = floorVenue(16.0f, 0.5f);
  const FrameState frame = goboSideFrame();
  run("gobo_side_high", venue, frame, high(kWidth, kHeight), 0.03);
  run("gobo_side_default", venue, frame, standard(kWidth, kHeight), 0.08);
}

// At 1280x960 the default preset scatters at half resolution (a quarter of the fragments) with
// a depth-aware upsample: the gobo's pattern in the beam is the detail that loses most.
TEST_F(BeamsVsReference, GoboSpotFromTheSideHd) {
  const Venue venue = floorVenue(16.0f, 0.5f);
  const FrameState frame = goboSideFrame();
  const RenderSettings s = standard(1280, 960);
  ASSERT_EQ(s.scatterDivisor, 2) << "the preset this test is about";
  run("gobo_side_default_hd", venue, frame, s, 0.08);
}

// Eight coloured fixtures crossing around a set piece (a box that shadows some of them).
TEST_F(BeamsVsReference, EightColouredBeamsAroundASetPiece) {
  Venue venue = floorVenue(20.0f, 0.4f);
  venue.materials.push_back(Material{.name = "set", .baseColor = glm::vec4(0.6f, 0.6f, 0.6f, 1.0f)});
  addBox(venue, {-0.6f, 0.0f, -0.6f}, {0.6f, 2.4f, 0.6f});
  FrameState frame;
  frame.camera.position = {0.0f, 4.0f, 13.0f};
  frame.camera.target = {0.0f, 2.0f, 0.0f};
  frame.camera.fovYDeg = 50.0f;
  frame.medium.scattering = 0.04f;
  frame.medium.ambient = glm::vec3(0.01f);
  for (int i = 0; i < 8; ++i) {
    const float a = static_cast<float>(i) * 3.14159265f / 4.0f;
    const glm::vec3 pos(5.0f * std::cos(a), 7.0f, 5.0f * std::sin(a));
    const glm::vec3 target(-1.5f * std::cos(a), 0.0f, -1.5f * std::sin(a));
    const glm::vec3 colour(0.5f + 0.5f * std::cos(a), 0.5f + 0.5f * std::cos(a - 2.1f), 0.5f + 0.5f * std::cos(a + 2.1f));
    BeamState b = makeBeam(pos, target - pos, 12.0f, 18.0f, 40000.0f, colour);
    b.poseKey = static_cast<uint64_t>(i + 1);
    frame.beams.push_back(b);
  }
  run("eight_beams_high", venue, frame, high(kWidth, kHeight), 0.03);
  run("eight_beams_default", venue, frame, standard(kWidth, kHeight), 0.08);
}

// The camera inside a beam looking towards the lamp: strong forward scattering of the hazy
// phase function, and the 1/r^2 peak near the lens.
TEST_F(BeamsVsReference, CameraInsideBeamLookingAtTheLamp) {
  Venue venue = floorVenue(20.0f, 0.3f);
  FrameState frame;
  frame.camera.position = {0.0f, 1.6f, 3.0f};
  frame.camera.target = {0.0f, 6.0f, -1.0f};
  frame.camera.fovYDeg = 60.0f;
  frame.medium.scattering = 0.03f;
  const glm::vec3 lens(0.0f, 7.0f, -2.0f);
  frame.beams.push_back(makeBeam(lens, frame.camera.position - lens, 24.0f, 36.0f, 30000.0f));
  // No lens disc here: its few pixels (millions of cd/m^2) would set the 1 % threshold of the
  // comparison and leave the in-scattering, which this test is about, unselected. The disc
  // itself is checked in lens_test.cpp.
  frame.beams.back().optics.lensRadiusM = 0.0f;
  run("inside_beam_high", venue, frame, high(kWidth, kHeight), 0.03);
  run("inside_beam_default", venue, frame, standard(kWidth, kHeight), 0.08);
}

}  // namespace
}  // namespace haze::test
