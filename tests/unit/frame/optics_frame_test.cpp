// The frame builder's optics: spinning wheels stand at rotation + spin * clock, a prism becomes
// N beams of 1/N, a still strobe gives its duty and a frame at a moment the gate's state, and
// every cell of a multi-cell fixture passes the fixture's shutter, blades, frost and prism.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "fixtures/blades.h"
#include "fixtures/cells.h"
#include "fixtures/photometry.h"
#include "fixtures/prism.h"
#include "shows/frame/frame_builder.h"

namespace haze {
namespace {

// One 16-degree spot (profile "spot", fixture 1) hanging at 5 m, for the frame builder's tests.
Show oneSpotShow(const char* file) {
  Show show;
  show.file = file;
  show.fixtures.push_back(FixtureDef{.id = 1, .name = "", .profile = "spot", .mode = "", .position = {0, 5, 0}, .rotationDeg = {}, .patch = {}});
  return show;
}
std::shared_ptr<Profile> spotProfile() {
  auto profile = std::make_shared<Profile>();
  auto d = parametricDistribution(10.0f, 16.0f, 1000.0f);
  EXPECT_TRUE(d.ok());
  if (d.ok()) profile->distribution = std::make_shared<const Distribution>(*d);
  profile->fieldAngleDeg = 16.0f;
  profile->zoomDeg = {16.0f, 16.0f};
  return profile;
}

TEST(OpticsFrame, SpinningWheelsStandAtRotationPlusSpinTimesTheClock) {
  const Show show = oneSpotShow("spin.haze.json");
  ProfileSet profiles{{"spot", spotProfile()}};
  StageState stage;
  Attributes a;
  a.intensity = 1.0f;
  a.goboRotationDeg = 10.0f;
  a.goboSpinDegS = 30.0f;
  a.gobo2RotationDeg = -5.0f;
  a.gobo2SpinDegS = -20.0f;
  stage[1] = a;
  for (double t : {0.0, 0.5, 2.0}) {
    auto f = buildFrame(show, profiles, stage, "", FrameOptions{.clockS = t});
    ASSERT_TRUE(f.ok());
    ASSERT_EQ(f->beams.size(), 1u);
    EXPECT_NEAR(f->beams[0].optics.goboRotationDeg, 10.0 + 30.0 * t, 1e-4) << t;
    EXPECT_NEAR(f->beams[0].optics.gobo2RotationDeg, -5.0 - 20.0 * t, 1e-4) << t;
  }
  // Different angles are different light maps.
  auto f0 = buildFrame(show, profiles, stage, "", FrameOptions{.clockS = 0.0});
  auto f1 = buildFrame(show, profiles, stage, "", FrameOptions{.clockS = 1.0});
  ASSERT_TRUE(f0.ok() && f1.ok());
  EXPECT_NE(f0->beams[0].opticsKey, f1->beams[0].opticsKey);
}

TEST(OpticsFrame, PrismBecomesNBeamsAndAStillStrobeItsDuty) {
  const Show show = oneSpotShow("optics.haze.json");
  auto profile = spotProfile();
  profile->prisms.push_back(PrismSpec{"5", 5, 10.0f, false});
  ProfileSet profiles{{"spot", profile}};
  StageState stage;
  Attributes a;
  a.intensity = 0.8f;
  a.prism = "5";
  a.shutter = Shutter{ShutterMode::Strobe, 30.0f, 0.25f};
  stage[1] = a;
  auto still = buildFrame(show, profiles, stage, "");
  ASSERT_TRUE(still.ok()) << still.error().str();
  ASSERT_EQ(still->beams.size(), 5u);
  for (const BeamState& b : still->beams) {
    EXPECT_NEAR(b.optics.dimmer, 0.8f * 0.25f / 5.0f, 1e-6f);
    EXPECT_NEAR(std::acos(glm::dot(b.pose.zb, glm::vec3(0, -1, 0))), 10.0f * 3.14159265f / 180.0f, 1e-4f);
  }
  // A frame at a moment: open for the first quarter of each 1/30 s period, closed after.
  auto open = buildFrame(show, profiles, stage, "", FrameOptions{.time = FrameTime{0.001, 0.0}});
  ASSERT_TRUE(open.ok());
  ASSERT_EQ(open->beams.size(), 5u);
  EXPECT_NEAR(open->beams[0].optics.dimmer, 0.8f / 5.0f, 1e-6f);
  auto closed = buildFrame(show, profiles, stage, "", FrameOptions{.time = FrameTime{0.02, 0.0}});
  ASSERT_TRUE(closed.ok());
  EXPECT_TRUE(closed->beams.empty());
}

// A wash of three cells on a row, `spacing` metres apart, with a 16-degree field.
std::shared_ptr<Profile> rowOfCells(float spacing) {
  auto profile = std::make_shared<Profile>();
  auto d = parametricDistribution(10.0f, 16.0f, 1000.0f);
  EXPECT_TRUE(d.ok());
  profile->distribution = std::make_shared<const Distribution>(*d);
  profile->fieldAngleDeg = 16.0f;
  profile->zoomDeg = {16.0f, 16.0f};
  for (float x : {-spacing, 0.0f, spacing}) {
    Cell c;
    c.name = "cell";
    c.lensOffset = {x, 0.0f, 0.0f};
    c.distribution = profile->distribution;
    c.fieldAngleDeg = 16.0f;
    profile->cells.push_back(c);
  }
  return profile;
}

// docs/cells.md, "Cost": `auto` (the default) draws a fixture's cells as one beam when they are
// driven alike and lie close enough for their cones to overlap within a metre (16 degrees:
// tan 8 degrees = 0.14 m), else one beam per cell; `separate` always one per cell.
TEST(OpticsFrame, AutoDrawsCellsDrivenAlikeAndPackedCloseAsOneBeam) {
  Show show;
  show.file = "cells.haze.json";
  show.fixtures.push_back(FixtureDef{.id = 1, .name = "", .profile = "wash", .mode = "", .position = {0, 5, 0}, .rotationDeg = {}, .patch = {}});
  const auto beamsOf = [&](float spacing, std::vector<CellAttributes> cells, CellBeams mode) {
    Attributes a;
    a.intensity = 0.8f;
    a.cells = std::move(cells);
    auto frame = buildFrame(show, ProfileSet{{"wash", rowOfCells(spacing)}}, StageState{{1, a}}, "", FrameOptions{.cells = mode});
    EXPECT_TRUE(frame.ok());
    return frame.ok() ? frame->beams : std::vector<BeamState>{};
  };
  const CellAttributes white{1.0f, glm::vec3(1.0f)};
  const std::vector<CellAttributes> alike{white, white, white};
  // Alike and 0.1 m from the centre: one beam with the three cells' light, at their centre, its
  // lens disc covering theirs.
  const auto one = beamsOf(0.1f, alike, CellBeams::Auto);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_NEAR(one[0].optics.dimmer, 3.0f * 0.8f, 1e-5f);
  EXPECT_NEAR(one[0].pose.lensPosition.x, 0.0f, 1e-6f);
  EXPECT_NEAR(one[0].optics.lensRadiusM, 0.1f + BeamOptics::kDefaultLensRadiusM, 1e-6f);
  EXPECT_EQ(one[0].cell, -1);
  EXPECT_EQ(beamsOf(0.1f, alike, CellBeams::Separate).size(), 3u);
  // Levels that 8-bit DMX cannot tell apart are alike.
  EXPECT_EQ(beamsOf(0.1f, {white, {0.9995f, glm::vec3(1.0f)}, white}, CellBeams::Auto).size(), 1u);
  // Driven apart: a dimmer cell, a red cell, a dark cell (the two lit ones are alike, but the
  // fixture is not lit as one).
  EXPECT_EQ(beamsOf(0.1f, {white, {0.5f, glm::vec3(1.0f)}, white}, CellBeams::Auto).size(), 3u);
  EXPECT_EQ(beamsOf(0.1f, {white, {1.0f, glm::vec3(1.0f, 0.0f, 0.0f)}, white}, CellBeams::Auto).size(), 3u);
  EXPECT_EQ(beamsOf(0.1f, {white, {0.0f, glm::vec3(1.0f)}, white}, CellBeams::Auto).size(), 2u);
  // Alike but spread like a bar: 0.2 m from the centre is past tan 8 degrees x 1 m.
  EXPECT_EQ(beamsOf(0.2f, alike, CellBeams::Auto).size(), 3u);
}

// A multi-cell fixture (docs/cells.md): every lit cell passes the fixture's shutter, blades and
// frost, and the prism copies each cell's beam; --cells merged merges before the prism.
TEST(OpticsFrame, EveryCellGetsTheShutterBladesFrostAndPrism) {
  Show show;
  show.file = "cells.haze.json";
  show.fixtures.push_back(FixtureDef{.id = 1, .name = "", .profile = "wash", .mode = "", .position = {0, 5, 0}, .rotationDeg = {}, .patch = {}});
  auto profile = rowOfCells(0.1f);
  profile->prisms.push_back(PrismSpec{"3", 3, 10.0f, false});
  profile->hasBlades = true;
  profile->hasFrost = true;
  ProfileSet profiles{{"wash", profile}};
  Attributes a;
  a.intensity = 0.8f;
  a.prism = "3";
  a.shutter = Shutter{ShutterMode::Strobe, 30.0f, 0.25f};
  a.blades[0] = {0.3f, 0.3f};
  a.frost = 0.5f;
  a.cells = {CellAttributes{1.0f, glm::vec3(1.0f)}, CellAttributes{0.0f, glm::vec3(1.0f)}, CellAttributes{0.5f, glm::vec3(1.0f)}};
  const StageState stage{{1, a}};
  auto frame = buildFrame(show, profiles, stage, "");
  ASSERT_TRUE(frame.ok()) << frame.error().str();
  ASSERT_EQ(frame->beams.size(), 6u);  // 2 lit cells x 3 facets
  const BladeMask mask = bladeMask(a.blades, 0.0f);
  for (const BeamState& b : frame->beams) {
    const float cell = b.cell == 0 ? 1.0f : 0.5f;
    ASSERT_TRUE(b.cell == 0 || b.cell == 2);
    EXPECT_NEAR(b.optics.dimmer, 0.8f * cell * 0.25f / 3.0f, 1e-6f);
    EXPECT_TRUE(b.optics.blades == mask);
    EXPECT_NE(b.optics.distribution.get(), profile->distribution.get());  // frosted
    EXPECT_EQ(b.opticsKey, frame->beams.front().opticsKey);
    EXPECT_NEAR(std::acos(glm::dot(b.pose.zb, glm::vec3(0, -1, 0))), 10.0f * 3.14159265f / 180.0f, 1e-4f);
  }
  // Without blades the light map differs, so the key does.
  Attributes clear = a;
  clear.blades = {};
  auto unbladed = buildFrame(show, profiles, StageState{{1, clear}}, "");
  ASSERT_TRUE(unbladed.ok());
  EXPECT_NE(unbladed->beams.front().opticsKey, frame->beams.front().opticsKey);
  // Merged: the two alike cells become one beam, then three prism copies of it.
  auto merged = buildFrame(show, profiles, stage, "", FrameOptions{.cells = CellBeams::Merged});
  ASSERT_TRUE(merged.ok());
  ASSERT_EQ(merged->beams.size(), 3u);
  for (const BeamState& b : merged->beams) EXPECT_NEAR(b.optics.dimmer, 0.8f * 1.5f * 0.25f / 3.0f, 1e-6f);
  // A moment when the shutter is closed: no cell draws.
  auto closed = buildFrame(show, profiles, stage, "", FrameOptions{.time = FrameTime{0.02, 0.0}});
  ASSERT_TRUE(closed.ok());
  EXPECT_TRUE(closed->beams.empty());
}

}  // namespace
}  // namespace haze
