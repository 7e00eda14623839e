// Large rigs: with 1000 fixtures at the default preset every beam in view must draw.
// Its 1000 shadow maps of 1024 px (4 GB) once failed to fit llvmpipe's 1 GB per texture and
// every beam vanished without a word. That limit comes from the maps' size, not the image's,
// so a 320x180 image shows it as well as 1280x720 does, in a fraction of the time.
//
// The independent check: light adds up, so the frame equals the sum of the same frame rendered
// in batches of 50 fixtures (each batch far from any limit), less the beamless frame counted
// once per extra batch. The in-scattering's jitter is per pixel, not per beam, so the sums
// agree to float rounding; a missing beam leaves its own pixels short by all of its light.
#include <algorithm>
#include <cmath>

#include "app/bench_scene.h"
#include "app/render_session.h"
#include "render_test_util.h"
#include "renderer/gl/gl.h"
#include "renderer/renderer.h"
#include "shows/scene/camera_basis.h"

namespace haze::test {
namespace {

class LargeRigTest : public GlTest {};

constexpr int kWidth = 320, kHeight = 180;

ImageRGB renderFrame(const Venue& venue, const FrameState& frame, const RenderSettings& s, PassTimes* times,
                     std::vector<std::string>* warnings) {
  auto r = Renderer::create(venue, s);
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
  if (!r.ok()) return {};
  (*r)->render(frame);
  if (times) *times = (*r)->lastTimes();
  if (warnings) *warnings = (*r)->warnings();
  return (*r)->readRadiance();
}

// Lenses in front of the camera and inside the image: their beams are certainly in view.
int lensesInView(const FrameState& frame) {
  const float aspect = static_cast<float>(kWidth) / static_cast<float>(kHeight);
  const CameraBasis b = cameraBasis(frame.camera, aspect);
  int n = 0;
  for (const BeamState& beam : frame.beams) {
    const glm::vec3 d = beam.pose.lensPosition - frame.camera.position;
    const float z = glm::dot(d, b.forward);
    if (z <= frame.camera.nearM) continue;
    const float x = glm::dot(d, b.right) / (z * b.tanX), y = glm::dot(d, b.up) / (z * b.tanY);
    n += std::abs(x) < 1.0f && std::abs(y) < 1.0f;
  }
  return n;
}

TEST_F(LargeRigTest, ThousandFixturesAtDefaultEveryBeamContributes) {
  constexpr int kFixtures = 1000, kBatch = 50;
  const Venue venue = benchVenue(kFixtures);
  const FrameState frame = benchFrame(kFixtures);
  RenderSettings s = renderSettingsFor(Quality::Default, kWidth, kHeight);
  s.timePasses = true;
  PassTimes times;
  std::vector<std::string> warnings;
  const ImageRGB full = renderFrame(venue, frame, s, &times, &warnings);
  ASSERT_FALSE(full.pixels.empty());
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  const int inView = lensesInView(frame);
  ASSERT_GT(inView, kFixtures * 9 / 10) << "the bench camera frames the rig";
  EXPECT_GE(times.beamsDrawn, inView);
  EXPECT_GT(times.scatteringFragments, 0u);

  // Batches with the maps at the full frame's size, so that only the beam count differs.
  RenderSettings batchSettings = s;
  batchSettings.shadowMapSize = times.shadowMapSize;
  auto batchRenderer = Renderer::create(venue, batchSettings);  // one for all batches: programs built once
  ASSERT_TRUE(batchRenderer.ok()) << batchRenderer.error().str();
  FrameState part = frame;
  part.beams.clear();
  (*batchRenderer)->render(part);
  const ImageRGB base = (*batchRenderer)->readRadiance();
  std::vector<glm::vec3> sum(full.pixels.size(), glm::vec3(0.0f));
  int batches = 0;
  for (int first = 0; first < kFixtures; first += kBatch, ++batches) {
    part.beams.assign(frame.beams.begin() + first, frame.beams.begin() + std::min(first + kBatch, kFixtures));
    (*batchRenderer)->render(part);
    EXPECT_TRUE((*batchRenderer)->warnings().empty());
    const ImageRGB img = (*batchRenderer)->readRadiance();
    ASSERT_EQ(img.pixels.size(), sum.size());
    for (size_t i = 0; i < sum.size(); ++i) sum[i] += img.pixels[i] - base.pixels[i];
  }
  float maxL = 0.0f;
  for (size_t i = 0; i < sum.size(); ++i) {
    sum[i] += base.pixels[i];
    maxL = std::max({maxL, full.pixels[i].r, full.pixels[i].g, full.pixels[i].b});
  }
  // Over the pixels a beam lights noticeably: the relative difference, worst pixel and channel.
  float worst = 0.0f;
  size_t lit = 0;
  for (size_t i = 0; i < sum.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      if (sum[i][c] < 1e-3f * maxL) continue;
      ++lit;
      worst = std::max(worst, std::abs(full.pixels[i][c] - sum[i][c]) / sum[i][c]);
    }
  std::printf("[ large_rig ] %d beams drawn, %d lenses in view, shadow maps %d px; %d batches; worst relative "
              "difference %.2e over %zu values\n", times.beamsDrawn, inView, times.shadowMapSize, batches, worst, lit);
  ASSERT_GT(lit, sum.size() / 10);
  EXPECT_LT(worst, 1e-3f);
}

// Past the GL's texture-array limit (one shadow-map layer per beam) the beams left out are named.
TEST_F(LargeRigTest, BeamsPastTheLayerLimitAreNamed) {
  GLint maxLayers = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
  ASSERT_GT(maxLayers, 0);
  const int fixtures = maxLayers + 3;
  const Venue venue = benchVenue(16);
  FrameState frame = benchFrame(16);
  const BeamState one = frame.beams.front();
  frame.beams.assign(static_cast<size_t>(fixtures), one);
  for (int i = 0; i < fixtures; ++i) {
    frame.beams[static_cast<size_t>(i)].fixtureId = i + 1;
    frame.beams[static_cast<size_t>(i)].poseKey = static_cast<uint64_t>(i + 1);
  }
  RenderSettings s{.width = 32, .height = 18, .shadowMapSize = 64};
  std::vector<std::string> warnings;
  PassTimes times;
  (void)renderFrame(venue, frame, s, &times, &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  const std::string expected = "fixtures " + std::to_string(maxLayers + 1) + "-" + std::to_string(fixtures) +
                               " not drawn (3 of " + std::to_string(fixtures) + " beams)";
  EXPECT_EQ(warnings[0].substr(0, expected.size()), expected) << warnings[0];
  EXPECT_NE(warnings[0].find("texture array layers"), std::string::npos) << warnings[0];
  EXPECT_EQ(times.beamsDrawn, maxLayers);
}

}  // namespace
}  // namespace haze::test
