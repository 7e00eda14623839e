// The GPU renderer (virtual planes on llvmpipe) against the CPU reference on the in-scattered
// radiance L_in (image_compare.h, compareBeams): the mean relative error over the beam cores
// and over the wider mask, and the leak where the reference is dark (docs/rendering.md,
// "Accuracy"). The remaining error is the planes' sampling noise, the light-map and shadow-map
// resolution, and rasterised (not traced) silhouettes; failing runs write actual/expected/diff
// PFMs of L_in into the build tree's test-output/ and print where.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <vector>

#include <glm/geometric.hpp>

#include "app/render_session.h"
#include "fixtures/body.h"
#include "fixtures/pose.h"
#include "render_test_util.h"
#include "renderer/reference/reference.h"
#include "renderer/renderer.h"
#include "shows/scene/bvh.h"
#include "shows/scene/image_compare.h"
#include "test_data.h"

namespace haze::test {
namespace {

// Images at 320x240, where every preset scatters at full resolution; the default preset's half
// resolution scattering at HD is tested on the hardest scene (the gobo) in GoboSpotFromTheSideHd.
constexpr int kWidth = 320, kHeight = 240;
// The scenes added for narrow beams, lamps and shafts: smaller, for the reference time.
constexpr int kSmallW = 240, kSmallH = 180;
constexpr double kOpen = 1e9;  // draft: printed with HAZE_TEST_DRAFT, not asserted

class BeamsVsReference : public GlTest {
 protected:
  struct Limits {
    double core, wide;     // mean relative error over the beam cores and over the wider mask
    double leak = 1.0;     // fraction of the reference's dark values the image lights
    size_t minCore = 40, minWide = 200, minDark = 0;  // enough values for the means to mean something
    // Wide-mask values off by more than half (image_compare.h): 0 measured on most scenes, so
    // 0.05 % holds them and still sees a dim beam left out beside a bright one (0.096 %).
    double gross = 0.0005;
  };
  // The reference images of a scene, made once per test for every preset.
  // HAZE_TEST_REFERENCE_CACHE=DIR keeps them as PFMs there between runs (for measuring a
  // change to the renderer many times; the reference must not change meanwhile).
  const ReferenceImages& reference(const std::string& scene, const Venue& venue, const FrameState& frame, int width,
                                   int height) {
    if (ref_.total.width == width && ref_.total.height == height) return ref_;
    const char* cache = std::getenv("HAZE_TEST_REFERENCE_CACHE");
    const std::filesystem::path base = cache ? std::filesystem::path(cache) / (scene + "_" + std::to_string(width)) : "";
    if (cache) {
      auto total = readPfm(base.string() + ".total.pfm"), in = readPfm(base.string() + ".in.pfm");
      if (total.ok() && in.ok() && total->width == width && total->height == height) {
        ref_.total = std::move(*total);
        ref_.inScattered = std::move(*in);
        return ref_;
      }
    }
    const Bvh bvh(venue);
    ref_ = renderReferenceImages(bvh, frame, width, height);
    if (cache) {
      std::error_code ec;
      std::filesystem::create_directories(cache, ec);
      EXPECT_TRUE(writePfm(ref_.total, base.string() + ".total.pfm").ok());
      EXPECT_TRUE(writePfm(ref_.inScattered, base.string() + ".in.pfm").ok());
    }
    return ref_;
  }
  // Renders, compares (image_compare.h, compareBeams) and fails the test above the limits;
  // only then (or with HAZE_TEST_IMAGES set) are the PFMs written, so passing runs leave
  // nothing behind.
  // Returns the GPU's L_in.
  ImageRGB run(const std::string& scene, const std::string& name, const Venue& venue, const FrameState& frame,
               RenderSettings settings, const Limits& limits) {
    auto r = Renderer::create(venue, settings);
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
    if (!r.ok()) return {};
    // The GPU's L_in: its image less the same frame without in-scattering (the extinction
    // kept, so the surfaces and lenses are the same to the last bit).
    FrameState dry = frame;
    dry.medium.absorption = frame.medium.extinction();
    dry.medium.scattering = 0.0f;
    (*r)->render(dry);
    ImageRGB gpu = (*r)->readRadiance();
    (*r)->render(frame);
    const ImageRGB wet = (*r)->readRadiance();
    for (size_t i = 0; i < gpu.pixels.size() && i < wet.pixels.size(); ++i) gpu.pixels[i] = wet.pixels[i] - gpu.pixels[i];
    const ReferenceImages& ref = reference(scene, venue, frame, settings.width, settings.height);
    const auto c = compareBeams(gpu, ref.inScattered);
    bool passed = c.ok();
    if (c) {
      std::printf("[ %s ] planes %d, divisor %d, frames %d: mean relative error %.4f over %zu core values, "
                  "%.4f over %zu wide values; leak %.5f of %zu dark values; gross %.5f\n",
                  name.c_str(), settings.planes, settings.scatterDivisor, settings.frames, c->coreError,
                  c->coreValues, c->wideError, c->wideValues, c->leak(), c->darkValues, c->gross());
      EXPECT_GE(c->coreValues, limits.minCore) << name << ": too few beam-core values compared";
      EXPECT_GE(c->wideValues, limits.minWide) << name << ": too few wide-mask values compared";
      EXPECT_GE(c->darkValues, limits.minDark) << name << ": too few dark values to measure a leak";
      EXPECT_LT(c->coreError, limits.core) << name << " (beam cores)";
      EXPECT_LT(c->wideError, limits.wide) << name << " (wide mask)";
      EXPECT_LE(c->leak(), limits.leak) << name << " (light where the reference is dark)";
      EXPECT_LE(c->gross(), limits.gross) << name << " (values off by more than half)";
      passed = within(*c, limits) &&
               c->coreValues >= limits.minCore && c->wideValues >= limits.minWide && c->darkValues >= limits.minDark;
    } else {
      ADD_FAILURE() << name << ": " << c.error().str();
    }
    if (!passed || std::getenv("HAZE_TEST_IMAGES"))
      for (const auto& file : writeDiagnostics(name, gpu, ref.inScattered))
        std::printf("[ %s ] wrote %s\n", name.c_str(), file.c_str());
    if (passed && limits.core < kOpen) expectTeeth(name, **r, frame, gpu, ref.inScattered, limits);
    return gpu;
  }
  static bool within(const BeamComparison& c, const Limits& l) {
    return c.coreError < l.core && c.wideError < l.wide && c.leak() <= l.leak && c.gross() <= l.gross;
  }
  // The limits have teeth: the same comparison fails the image made wrong on purpose. Brighter
  // by 10 %, it must fail every scene (a limit that passes it could not see a 10 % error); with
  // a beam left out (scenes of several beams, at default only, for the test's time), it must
  // fail; an image of another size is an error, not a match.
  void expectTeeth(const std::string& name, Renderer& r, const FrameState& frame, const ImageRGB& gpu,
                   const ImageRGB& ref, const Limits& limits) {
    ImageRGB brighter = gpu;
    for (glm::vec3& p : brighter.pixels) p *= 1.1f;
    const auto b = compareBeams(brighter, ref);
    ASSERT_TRUE(b.ok());
    EXPECT_FALSE(within(*b, limits)) << name << ": the limits pass the image scaled by 1.1 (cores "
                                     << b->coreError << ", wide " << b->wideError << ")";
    ImageRGB cropped = gpu;
    cropped.height -= 1;
    cropped.pixels.resize(static_cast<size_t>(cropped.width) * cropped.height);
    EXPECT_FALSE(compareBeams(cropped, ref).ok()) << name << ": an image one row short compared";
    std::printf("[ %s ] teeth: scaled by 1.1 %.4f / %.4f (cores / wide)\n", name.c_str(), b->coreError, b->wideError);
    if (frame.beams.size() < 2 || name.find("_default") == std::string::npos) return;
    FrameState fewer = frame;
    fewer.beams.pop_back();
    FrameState dry = fewer;
    dry.medium.absorption = fewer.medium.extinction();
    dry.medium.scattering = 0.0f;
    r.render(dry);
    ImageRGB missing = r.readRadiance();
    r.render(fewer);
    const ImageRGB wet = r.readRadiance();
    for (size_t i = 0; i < missing.pixels.size() && i < wet.pixels.size(); ++i) missing.pixels[i] = wet.pixels[i] - missing.pixels[i];
    const auto m = compareBeams(missing, ref);
    ASSERT_TRUE(m.ok());
    EXPECT_FALSE(within(*m, limits)) << name << ": the limits pass the image with a beam left out (cores "
                                     << m->coreError << ", wide " << m->wideError << ")";
    std::printf("[ %s ] teeth: a beam left out %.4f / %.4f (cores / wide), gross %.5f\n", name.c_str(),
                m->coreError, m->wideError, m->gross());
  }
  // Every scene at high and default against the limits; with HAZE_TEST_DRAFT set, draft is
  // measured too (printed, not asserted: draft promises speed, not accuracy).
  void presets(const std::string& name, const Venue& venue, const FrameState& frame, int w, int h,
               const Limits& high, const Limits& standard) {
    run(name, name + "_high", venue, frame, renderSettingsFor(Quality::High, w, h), high);
    run(name, name + "_default", venue, frame, renderSettingsFor(Quality::Default, w, h), standard);
    if (std::getenv("HAZE_TEST_DRAFT"))
      run(name, name + "_draft", venue, frame, renderSettingsFor(Quality::Draft, w, h), {kOpen, kOpen, 1.0, 0, 0, 0, 1.0});
  }
  ReferenceImages ref_;
};

// Limits per scene: the errors measured on llvmpipe (docs/rendering.md, "Accuracy"; the
// jitter is deterministic, so a run repeats them) times 1.5, or plus 0.2 points where that is
// more, and never above 3 % / 2 % at high and 8 % / 5 % at default where the
// measured error is below them. Where it is not, the limit is the measured error plus a
// quarter and the comment says so. No limit here is open.

// One spot in haze with a sphere in its beam, seen from the front (the floor pool behind).
TEST_F(BeamsVsReference, SpotWithSphereShadowShaft) {
  Venue venue = floorVenue(16.0f, 0.4f);
  addSphere(venue, {0.0f, 3.0f, 0.0f}, 0.5f);
  FrameState frame;
  frame.camera.position = {0.0f, 3.0f, 10.0f};
  frame.camera.target = {0.0f, 2.5f, 0.0f};
  frame.camera.fovYDeg = 45.0f;
  frame.medium.scattering = 0.05f;
  frame.beams.push_back(makeBeam({0.0f, 7.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 20.0f, 30.0f, 50000.0f));
  presets("sphere_front", venue, frame, kWidth, kHeight, {0.005, 0.005}, {0.025, 0.025});
}

// The sphere's shadow shaft seen from the side: each ray crosses lit haze, the shaft, lit haze.
FrameState shaftFrame() {
  FrameState frame;
  frame.camera.position = {9.0f, 3.0f, 0.0f};
  frame.camera.target = {0.0f, 3.0f, 0.0f};
  frame.camera.fovYDeg = 50.0f;
  frame.medium.scattering = 0.05f;
  frame.beams.push_back(makeBeam({0.0f, 7.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 20.0f, 30.0f, 50000.0f));
  return frame;
}
Venue shaftVenue() {
  Venue venue = floorVenue(16.0f, 0.4f);
  addSphere(venue, {0.0f, 4.0f, 0.0f}, 0.5f);
  return venue;
}

// The whole image as every scene, and the haze inside the shaft itself: the pixels whose rays
// the sphere darkens by more than a fifth (the reference with and without the sphere), where
// the GPU's L_in must be neither brighter nor darker than the reference's on average (a
// washed-out shaft is brighter).
TEST_F(BeamsVsReference, ShadowShaftFromTheSide) {
  const FrameState frame = shaftFrame();
  const ImageRGB open = renderReferenceImages(Bvh(floorVenue(16.0f, 0.4f)), frame, kSmallW, kSmallH).inScattered;
  const ImageRGB& shaded = reference("shaft_side", shaftVenue(), frame, kSmallW, kSmallH).inScattered;
  float openMax = 0.0f;
  for (const glm::vec3& p : open.pixels) openMax = std::max(openMax, p.g);
  std::vector<size_t> shaft;
  for (size_t i = 0; i < open.pixels.size(); ++i)
    if (open.pixels[i].g > 0.02f * openMax && shaded.pixels[i].g < 0.8f * open.pixels[i].g) shaft.push_back(i);
  ASSERT_GE(shaft.size(), 300u) << "the shaft covers too few pixels to measure";
  const bool draft = std::getenv("HAZE_TEST_DRAFT") != nullptr;
  for (Quality q : {Quality::High, Quality::Default, Quality::Draft}) {
    if (q == Quality::Draft && !draft) continue;
    const char* label = q == Quality::High ? "high" : q == Quality::Default ? "default" : "draft";
    const Limits limits = q == Quality::High ? Limits{0.003, 0.0038} : q == Quality::Default ? Limits{0.0056, 0.024}
                                                                                            : Limits{kOpen, kOpen};
    const ImageRGB gpu = run("shaft_side", std::string("shaft_side_") + label, shaftVenue(), frame,
                             renderSettingsFor(q, kSmallW, kSmallH), limits);
    ASSERT_EQ(gpu.pixels.size(), shaded.pixels.size());
    double bias = 0.0, error = 0.0;
    for (size_t i : shaft) {
      const double e = (double(gpu.pixels[i].g) - shaded.pixels[i].g) / shaded.pixels[i].g;
      bias += e;
      error += std::abs(e);
    }
    bias /= double(shaft.size());
    error /= double(shaft.size());
    std::printf("[ shaft_side_%s ] in the shaft: %zu shaft pixels: mean relative error %.4f, mean signed %.4f\n", label,
                shaft.size(), error, bias);
    if (q == Quality::Draft) continue;
    // Measured at high 0.58 % (bias 0.11 %), at default 3.96 % (bias 0.09 %): noise, no
    // wash-out (7.0 % at default before chords that cross a hard shadow's edge were walked
    // twice, planes.frag.glsl).
    EXPECT_LT(error, q == Quality::High ? 0.009 : 0.06) << label;
    EXPECT_LT(std::abs(bias), q == Quality::High ? 0.01 : 0.02) << label << ": the shaft is washed out or too dark";
  }
}

// The shaft scene with the sphere replaced by another fixture's body: a dark moving head hung
// 2.2 m under the spot's lens, a little off its axis (docs/physics.md, section 7: V(x) tests the
// bodies of every other fixture). The spot's own body, round its lens, casts nothing into it.
FrameState bodyShaftFrame() {
  FrameState frame = shaftFrame();
  frame.beams[0].fixtureId = 1;
  frame.beams[0].poseKey = frame.beams[0].opticsKey = 1;
  const glm::vec3 lensOffset(0.0f, -0.2f, 0.0f);
  const Body body = defaultBody(0.05f, {lensOffset}, true);
  poseBody(body, frame.beams[0].pose.lensPosition - lensOffset, glm::vec3(0.0f), 0.0f, 0.0f, frame.bodies);
  for (BodyBox& b : frame.bodies) b.fixtureId = 1;
  const size_t own = frame.bodies.size();
  poseBody(body, {0.12f, 4.6f, 0.0f}, glm::vec3(0.0f), 30.0f, 20.0f, frame.bodies);
  for (size_t k = own; k < frame.bodies.size(); ++k) frame.bodies[k].fixtureId = 2;
  return frame;
}

// The body's shaft seen from the side, as the sphere's above: the whole image against the
// reference, and the haze in the shaft (the pixels the body darkens by more than a fifth in the
// reference) neither washed out nor too dark on the GPU; both renderers must show the shaft.
TEST_F(BeamsVsReference, AnotherFixturesBodyCastsAShaft) {
  const FrameState frame = bodyShaftFrame();
  FrameState bare = frame;
  bare.bodies.clear();
  const Venue venue = floorVenue(16.0f, 0.4f);
  const ImageRGB open = renderReferenceImages(Bvh(venue), bare, kSmallW, kSmallH).inScattered;
  const ImageRGB& shaded = reference("body_shaft", venue, frame, kSmallW, kSmallH).inScattered;
  float openMax = 0.0f;
  for (const glm::vec3& p : open.pixels) openMax = std::max(openMax, p.g);
  std::vector<size_t> shaft;
  for (size_t i = 0; i < open.pixels.size(); ++i)
    if (open.pixels[i].g > 0.02f * openMax && shaded.pixels[i].g < 0.8f * open.pixels[i].g) shaft.push_back(i);
  std::printf("[ body_shaft ] %zu shaft pixels in the reference\n", shaft.size());
  ASSERT_GE(shaft.size(), 300u) << "the reference shows no shaft behind the body";
  for (Quality q : {Quality::High, Quality::Default}) {
    const char* label = q == Quality::High ? "high" : "default";
    // Measured at high 0.23 % / 0.20 % (cores / wide), at default 1.49 % / 1.30 %; limits by the
    // file's rule (plus 0.2 points at high, times 1.5 at default).
    const Limits limits = q == Quality::High ? Limits{0.0043, 0.004} : Limits{0.0224, 0.0195};
    const ImageRGB gpu = run("body_shaft", std::string("body_shaft_") + label, venue, frame,
                             renderSettingsFor(q, kSmallW, kSmallH), limits);
    ASSERT_EQ(gpu.pixels.size(), shaded.pixels.size());
    double bias = 0.0, error = 0.0, gpuShaft = 0.0, openShaft = 0.0;
    for (size_t i : shaft) {
      const double e = (double(gpu.pixels[i].g) - shaded.pixels[i].g) / shaded.pixels[i].g;
      bias += e;
      error += std::abs(e);
      gpuShaft += gpu.pixels[i].g;
      openShaft += open.pixels[i].g;
    }
    bias /= double(shaft.size());
    error /= double(shaft.size());
    std::printf("[ body_shaft_%s ] in the shaft: mean relative error %.4f, mean signed %.4f; GPU light there %.3f of "
                "the open beam's\n", label, error, bias, gpuShaft / openShaft);
    // Measured: the GPU keeps 0.488 of the open beam's light there at both presets; in the shaft
    // 0.76 % (bias 0.04 %) at high, 5.4 % (bias -0.01 %) at default: noise, no wash-out.
    EXPECT_LT(gpuShaft / openShaft, 0.7) << label << ": the GPU shows no shaft behind the body";
    EXPECT_LT(error, q == Quality::High ? 0.012 : 0.082) << label;
    EXPECT_LT(std::abs(bias), q == Quality::High ? 0.01 : 0.02) << label << ": the shaft is washed out or too dark";
  }
}

// Under the body, looking up at it through its shadow: the reference leaves the haze between
// the camera and the body dark; light there is a leak.
TEST_F(BeamsVsReference, InsideABodysShadowShaft) {
  FrameState frame = bodyShaftFrame();
  frame.camera.position = {0.27f, 1.6f, 0.02f};  // on the line from the lens through the body
  frame.camera.target = {0.12f, 4.6f, 0.0f};
  frame.camera.fovYDeg = 25.0f;
  // Measured 0.33 % at high, 2.93 % at default (one jittered frame); no leak at either over the
  // 4638 values the reference leaves dark (the body's own pixels, seen through its shadow).
  Limits high{0.0053, 0.0053, 0.001}, standard{0.044, 0.044, 0.001};
  high.minDark = standard.minDark = 4000;
  presets("body_shaft_inside", floorVenue(16.0f, 0.4f), frame, kSmallW, kSmallH, high, standard);
}

// Inside the shaft, under the sphere, looking up at it: every ray that meets the sphere runs in
// its shadow, so the reference leaves the sphere's disc dark; light there is a leak.
TEST_F(BeamsVsReference, InsideTheShadowShaft) {
  FrameState frame = shaftFrame();
  frame.camera.position = {0.0f, 1.2f, 0.5f};
  frame.camera.target = {0.0f, 4.0f, 0.0f};
  frame.camera.fovYDeg = 60.0f;
  // Measured 0.23 % at high and 3.59 % at default: noise of one jittered frame over chords
  // that leave the shadow at a different depth in every pixel, no bias and no leak. Those
  // chords see V change and are walked twice (planes.frag.glsl); with one walk of 16 strata
  // default was at 7.6 % and high at 0.79 %.
  Limits high{0.0045, 0.0045, 0.001}, standard{0.054, 0.05, 0.001};
  high.minDark = standard.minDark = 2000;
  presets("shaft_inside", shaftVenue(), frame, kSmallW, kSmallH, high, standard);
}

// The same view with the shadows a show gets by default (soft: the visible fraction of a 9 cm
// lens, docs/physics.md "Soft shadows"), reference and GPU alike. A point light's shadow is a
// step along every chord, which the walk follows by walking twice the chords that see V change;
// a real lens's penumbra is a ramp that one walk's strata integrate. Measured 0.89 % at high
// and 3.54 % at default; no leak at either.
TEST_F(BeamsVsReference, InsideTheSoftShadowShaft) {
  FrameState frame = shaftFrame();
  frame.camera.position = {0.0f, 1.2f, 0.5f};
  frame.camera.target = {0.0f, 4.0f, 0.0f};
  frame.camera.fovYDeg = 60.0f;
  frame.softShadows = true;
  frame.beams.back().optics.lensRadiusM = 0.09f;
  Limits high{0.0134, 0.0134, 0.001}, standard{0.053, 0.05, 0.001};
  high.minDark = standard.minDark = 2000;
  presets("soft_shaft_inside", shaftVenue(), frame, kSmallW, kSmallH, high, standard);
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
  presets("gobo_side", floorVenue(16.0f, 0.5f), goboSideFrame(), kWidth, kHeight, {0.012, 0.008}, {0.08, 0.05});
}

// The same beam with the lens defocused (docs/physics.md, "Focus": the gate blurred by 0.15 gate
// radii, focus at an end of the default range): in the haze too the GPU's light map and the
// reference's exact lookup agree, within the sharp gobo's limits.
TEST_F(BeamsVsReference, DefocusedGoboSpotFromTheSide) {
  FrameState frame = goboSideFrame();
  frame.beams[0].optics.focusBlur = 0.15f;
  presets("gobo_side_defocused", floorVenue(16.0f, 0.5f), frame, kWidth, kHeight, {0.012, 0.008}, {0.08, 0.05});
}

// At 1280x960 the default preset scatters at half resolution (a quarter of the fragments) with
// a depth-aware upsample, and refines at full resolution where the half-resolution values have
// detail: the gobo's pattern in the beam is the detail that loses most.
TEST_F(BeamsVsReference, GoboSpotFromTheSideHd) {
  const RenderSettings s = renderSettingsFor(Quality::Default, 1280, 960);
  ASSERT_EQ(s.scatterDivisor, 2) << "the preset this test is about";
  ASSERT_GT(s.refineCurvature, 0.0f) << "the preset this test is about";
  // Measured 7.50 % over the cores (the lens end of the beam, where the rings are finest on
  // screen) and 3.99 % over the wider mask, under the 8 % and 5 % wanted (docs/rendering.md);
  // without the refinement 11.8 % and 5.0 %. Values off by more than half: 0.059 % (0.455 %
  // without), the ring edges near the lens; no light where the reference is dark (0.024 %
  // without).
  run("gobo_side_hd", "gobo_side_default_hd", floorVenue(16.0f, 0.5f), goboSideFrame(), s,
      {0.08, 0.05, 0.0001, 40, 200, 0, 0.001});
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
  presets("eight_beams", venue, frame, kWidth, kHeight, {0.002, 0.003}, {0.003, 0.01});
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
  // No lens disc here: the disc is checked in lens_test.cpp; this is about the in-scattering.
  frame.beams.back().optics.lensRadiusM = 0.0f;
  presets("inside_beam", venue, frame, kWidth, kHeight, {0.01, 0.02}, {0.03, 0.045});
}

// Narrow beams, the concert's moving lights: 2, 4 and 10 degrees (parametric, field 1.5 times
// the beam), seen from the audience with the lamps in frame and their beams crossing.
TEST_F(BeamsVsReference, NarrowBeamsTwoFourTenDegrees) {
  Venue venue = floorVenue(24.0f, 0.3f);
  FrameState frame;
  frame.camera.position = {0.0f, 1.7f, 14.0f};
  frame.camera.target = {0.0f, 4.0f, 0.0f};
  frame.camera.fovYDeg = 45.0f;
  frame.medium.scattering = 0.04f;
  const float beamDeg[3] = {2.0f, 4.0f, 10.0f}, peakCd[3] = {2.0e6f, 8.0e5f, 2.0e5f};
  for (int i = 0; i < 3; ++i) {
    const float k = static_cast<float>(i);
    const glm::vec3 pos(-4.0f + 4.0f * k, 7.0f, -1.0f);
    const glm::vec3 target(2.0f - 2.0f * k, 0.0f, 3.0f);
    BeamState b = makeBeam(pos, target - pos, beamDeg[i], 1.5f * beamDeg[i], peakCd[i]);
    b.poseKey = b.opticsKey = static_cast<uint64_t>(i + 1);
    frame.beams.push_back(b);
  }
  presets("narrow_2_4_10", venue, frame, kSmallW, kSmallH, {0.002, 0.002}, {0.002, 0.004});
}

// The real 10-degree flood (EULUMDAT, 2.2 Mcd, light out to 90 degrees) crossing two IES spots,
// lamps in frame: a narrow core in a wide cutoff cone.
TEST_F(BeamsVsReference, LdtFloodCrossingIesSpots) {
  HAZE_NEED_DATA("photometry/ldt/eulumdat-rs/4058075580664_FL_MAX_LUM_1200W_757_SYM_10_WAL.ldt");
  Venue venue = floorVenue(24.0f, 0.3f);
  FrameState frame;
  frame.camera.position = {0.0f, 1.7f, 14.0f};
  frame.camera.target = {0.0f, 4.0f, 0.0f};
  frame.camera.fovYDeg = 45.0f;
  frame.medium.scattering = 0.03f;
  const glm::vec3 flood(0.0f, 7.0f, -2.0f);
  frame.beams.push_back(fileBeam("ldt/eulumdat-rs/4058075580664_FL_MAX_LUM_1200W_757_SYM_10_WAL.ldt", flood,
                                 glm::vec3(0.0f, 0.0f, 4.0f) - flood));
  const glm::vec3 left(-5.0f, 6.5f, 0.0f), right(5.0f, 6.5f, 0.0f);
  frame.beams.push_back(fileBeam("ies/hydraapi/ies_34.ies", left, glm::vec3(2.0f, 0.0f, 2.0f) - left));
  frame.beams.push_back(fileBeam("ies/hydraapi/ies_22.ies", right, glm::vec3(-2.0f, 0.0f, 2.0f) - right));
  for (size_t i = 0; i < frame.beams.size(); ++i) frame.beams[i].poseKey = frame.beams[i].opticsKey = i + 1;
  ASSERT_TRUE(frame.beams[0].optics.distribution);
  ASSERT_GT(frame.beams[0].optics.distribution->peakCd(), 2.0e6f) << "the 2.2 Mcd flood this test is about";
  presets("ldt_flood", venue, frame, kSmallW, kSmallH, {0.006, 0.008}, {0.015, 0.025});
}

// The camera 2 m from the lens of a 4-degree beam, beside it, looking down the beam: the
// chord's 1/r^2 changes fastest in the first metre.
TEST_F(BeamsVsReference, CameraTwoMetresFromALens) {
  Venue venue = floorVenue(24.0f, 0.3f);
  FrameState frame;
  const glm::vec3 lens(0.0f, 6.0f, 0.0f);
  frame.camera.position = lens + glm::vec3(1.6f, -0.6f, 1.0f);
  frame.camera.target = {0.0f, 3.0f, 3.0f};
  frame.camera.fovYDeg = 70.0f;
  frame.medium.scattering = 0.04f;
  frame.beams.push_back(makeBeam(lens, glm::vec3(0.0f, 0.0f, 6.0f) - lens, 4.0f, 6.0f, 8.0e5f));
  ASSERT_NEAR(glm::length(frame.camera.position - lens), 2.0f, 0.05f);
  presets("near_lens", venue, frame, kSmallW, kSmallH, {0.002, 0.002}, {0.005, 0.005});
}

}  // namespace
}  // namespace haze::test
