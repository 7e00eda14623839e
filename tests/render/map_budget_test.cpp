// Map work spread over frames (RenderSettings::mapWorkBudgetMs, docs/rendering.md): when a cue
// moves a whole rig, a budgeted renderer redraws the beams' maps a few per frame, the longest
// waiting first, and says how many beams are still drawn with old maps (PassTimes::mapsPending).
//
// The checks: with a budget so small that one map fits per frame, 8 moved beams catch up in 8
// frames, one map each, pending 7, 6, ..., 0; from then on the image is, bit for bit, the one an
// unbudgeted renderer makes of the same frames. A frame drawn with old shadow maps must read
// them through the matrices they were drawn with: the beams here turn about their lenses, so
// the venue's shadows (columns, the hanging panel) fall where the new maps put them, and the
// stale frame stays close to the caught-up one; the new pose's matrices on the old maps would
// move every shadow by the turn.
#include <cmath>
#include <cstdio>
#include <cstring>

#include "app/bench_scene.h"
#include "app/render_session.h"
#include "render_test_util.h"
#include "renderer/renderer.h"

namespace haze::test {
namespace {

class MapBudget : public GlTest {};

constexpr int kBeams = 8;
constexpr int kWidth = 192, kHeight = 108;
// Far under one map's time: every frame draws exactly the one map it must (the oldest).
constexpr double kTinyBudgetMs = 1e-6;
// The stale frame's relative L1 difference from the caught-up one: 0.0022 measured (the parts of
// the new cones outside the old maps' frusta are lit, the old reaches end the footprints); with
// the new pose's matrices on the old maps, 0.099. The limit lies 4.5 times above the first.
constexpr double kStaleLimit = 0.01;

RenderSettings settings(double budgetMs) {
  RenderSettings s = renderSettingsFor(Quality::Draft, kWidth, kHeight);
  s.shadowMapSize = 256;
  s.lightMapSize = 128;
  s.timePasses = true;
  s.mapWorkBudgetMs = budgetMs;
  return s;
}

bool bitEqual(const ImageRGB& a, const ImageRGB& b) {
  return a.width == b.width && a.height == b.height &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

bool finite(const ImageRGB& img) {
  for (const glm::vec3& p : img.pixels)
    if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b)) return false;
  return !img.pixels.empty();
}

// Sum of |a - b| over sum of b, all channels: the relative L1 difference.
double relativeL1(const ImageRGB& a, const ImageRGB& b) {
  double diff = 0.0, sum = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      diff += std::abs(static_cast<double>(a.pixels[i][c]) - b.pixels[i][c]);
      sum += std::abs(static_cast<double>(b.pixels[i][c]));
    }
  return diff / sum;
}

struct Pair {
  std::unique_ptr<Renderer> budgeted, unbudgeted;
};

Pair makePair(const Venue& venue) {
  auto b = Renderer::create(venue, settings(kTinyBudgetMs));
  auto u = Renderer::create(venue, settings(0.0));
  EXPECT_TRUE(b.ok() && u.ok());
  if (!b.ok() || !u.ok()) return {};
  return {std::move(*b), std::move(*u)};
}

TEST_F(MapBudget, MovedBeamsCatchUpOneShadowMapAFrame) {
  const Venue venue = benchVenue(kBeams);
  const FrameState before = benchFrame(kBeams), after = turnedBeams(before, 6.0f);
  Pair r = makePair(venue);
  ASSERT_TRUE(r.budgeted && r.unbudgeted);
  // Beams without any map get theirs at once, budget or not: the first frames agree.
  r.budgeted->render(before);
  r.unbudgeted->render(before);
  EXPECT_EQ(r.budgeted->lastTimes().shadowMapsRendered, kBeams);
  EXPECT_EQ(r.budgeted->lastTimes().mapsPending, 0);
  EXPECT_TRUE(bitEqual(r.budgeted->readRadiance(), r.unbudgeted->readRadiance()));

  ImageRGB stale;
  for (int frame = 1; frame <= kBeams; ++frame) {
    r.budgeted->render(after);
    r.unbudgeted->render(after);
    const PassTimes& t = r.budgeted->lastTimes();
    EXPECT_EQ(t.shadowMapsRendered, 1) << "frame " << frame;
    EXPECT_EQ(t.mapsPending, kBeams - frame) << "frame " << frame;
    EXPECT_EQ(r.unbudgeted->lastTimes().shadowMapsRendered, frame == 1 ? kBeams : 0);
    EXPECT_EQ(r.unbudgeted->lastTimes().mapsPending, 0);
    const ImageRGB img = r.budgeted->readRadiance();
    EXPECT_TRUE(finite(img)) << "frame " << frame;
    if (frame == 1) stale = img;
    if (t.mapsPending == 0) {
      EXPECT_TRUE(bitEqual(img, r.unbudgeted->readRadiance())) << "frame " << frame;
    }
  }
  // Nothing left to do: no map drawn, the same image still.
  r.budgeted->render(after);
  r.unbudgeted->render(after);
  EXPECT_EQ(r.budgeted->lastTimes().shadowMapsRendered, 0);
  EXPECT_EQ(r.budgeted->lastTimes().mapsPending, 0);
  const ImageRGB caughtUp = r.budgeted->readRadiance();
  EXPECT_TRUE(bitEqual(caughtUp, r.unbudgeted->readRadiance()));

  // The stale frame (7 of 8 beams on their old maps) against the caught-up one.
  const double staleDiff = relativeL1(stale, caughtUp);
  std::printf("[ map_budget ] stale frame vs caught up: relative L1 difference %.4f\n", staleDiff);
  EXPECT_LT(staleDiff, kStaleLimit);
  if (staleDiff >= kStaleLimit) writeDiagnostics("map_budget_stale", stale, caughtUp);

  // The budget lifted (a caller about to make a final image): every map in the frame again.
  r.budgeted->setMapWorkBudgetMs(0.0);
  r.budgeted->render(before);
  r.unbudgeted->render(before);
  EXPECT_EQ(r.budgeted->lastTimes().shadowMapsRendered, kBeams);
  EXPECT_EQ(r.budgeted->lastTimes().mapsPending, 0);
  EXPECT_TRUE(bitEqual(r.budgeted->readRadiance(), r.unbudgeted->readRadiance()));
}

// A beam patched while the others wait gets its maps in its first frame, outside the budget:
// it has no old map to fall back on, and a layer it never drew holds nothing it could read.
TEST_F(MapBudget, ANewBeamGetsItsMapAtOnce) {
  const Venue venue = benchVenue(kBeams);
  const FrameState all = benchFrame(kBeams);  // one distribution: one light map for all beams
  FrameState before = all;
  before.beams.pop_back();
  const FrameState after = turnedBeams(all, 6.0f);
  Pair r = makePair(venue);
  ASSERT_TRUE(r.budgeted && r.unbudgeted);
  r.budgeted->render(before);
  r.unbudgeted->render(before);
  EXPECT_EQ(r.budgeted->lastTimes().shadowMapsRendered, kBeams - 1);
  for (int frame = 1; frame < kBeams; ++frame) {
    r.budgeted->render(after);
    r.unbudgeted->render(after);
    const PassTimes& t = r.budgeted->lastTimes();
    // The new beam's map and the longest waiting one's in the first frame, one a frame after.
    EXPECT_EQ(t.shadowMapsRendered, frame == 1 ? 2 : 1) << "frame " << frame;
    EXPECT_EQ(t.lightMapsBaked, 0) << "frame " << frame;
    EXPECT_EQ(t.mapsPending, kBeams - 1 - frame) << "frame " << frame;
    const ImageRGB img = r.budgeted->readRadiance();
    EXPECT_TRUE(finite(img)) << "frame " << frame;
    if (t.mapsPending == 0) {
      EXPECT_TRUE(bitEqual(img, r.unbudgeted->readRadiance())) << "frame " << frame;
    }
  }
}

FrameState goboFrame(const std::vector<float>& rotationsDeg) {
  FrameState f = benchFrame(kBeams);
  const auto gobo = halfOpaqueGobo(64, true);  // +y half opaque: turning it changes the map, not the cone
  for (size_t i = 0; i < f.beams.size(); ++i) {
    f.beams[i].optics.gobo = gobo;
    f.beams[i].optics.goboRotationDeg = rotationsDeg[i];
    f.beams[i].opticsKey = 1000 + static_cast<uint64_t>(rotationsDeg[i]);
  }
  return f;
}

// Turning every beam's gobo to its own angle: 8 new light maps, one baked a frame. A beam that
// waits draws with its old map, so a stale frame is exactly the frame whose waiting beams still
// have their old gobo angle (a fresh renderer's image of it: nothing carries over between renders).
TEST_F(MapBudget, ChangedLightMapsCatchUpOneAFrame) {
  const Venue venue = benchVenue(kBeams);
  const std::vector<float> still(kBeams, 0.0f);
  std::vector<float> turnedDeg(kBeams);
  for (int i = 0; i < kBeams; ++i) turnedDeg[static_cast<size_t>(i)] = 20.0f + 15.0f * static_cast<float>(i);
  Pair r = makePair(venue);
  ASSERT_TRUE(r.budgeted && r.unbudgeted);
  r.budgeted->render(goboFrame(still));
  EXPECT_EQ(r.budgeted->lastTimes().lightMapsBaked, 1);  // one map shared by all
  EXPECT_EQ(r.budgeted->lastTimes().mapsPending, 0);
  const FrameState after = goboFrame(turnedDeg);
  for (int frame = 1; frame <= kBeams; ++frame) {
    r.budgeted->render(after);
    const PassTimes& t = r.budgeted->lastTimes();
    EXPECT_EQ(t.lightMapsBaked, 1) << "frame " << frame;
    EXPECT_EQ(t.shadowMapsRendered, 0) << "frame " << frame;
    EXPECT_EQ(t.mapsPending, kBeams - frame) << "frame " << frame;
    // The longest waiting first, ties in beam order: beams 0 .. frame - 1 have their new maps.
    std::vector<float> shown = still;
    for (int i = 0; i < frame; ++i) shown[static_cast<size_t>(i)] = turnedDeg[static_cast<size_t>(i)];
    const ImageRGB img = r.budgeted->readRadiance();
    ASSERT_TRUE(finite(img)) << "frame " << frame;
    EXPECT_TRUE(bitEqual(img, renderRadiance(venue, goboFrame(shown), settings(0.0)))) << "frame " << frame;
  }
  r.budgeted->render(after);
  EXPECT_EQ(r.budgeted->lastTimes().lightMapsBaked, 0);
  EXPECT_EQ(r.budgeted->lastTimes().mapsPending, 0);
}

}  // namespace
}  // namespace haze::test
