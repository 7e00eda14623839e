// Show + stage state -> FrameState: one beam per lit fixture (per cell, per prism facet), each
// at the fixture's lens with the stage's dimmer; dark fixtures add nothing; the cache keys follow
// what the renderer's maps depend on and nothing else; merged cells keep their light.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include <glm/geometric.hpp>

#include "shows/frame/atmosphere_field.h"
#include "shows/frame/cell_merge.h"
#include "shows/frame/frame_builder.h"
#include "shows/show_json.h"

namespace haze {
namespace {

const std::filesystem::path kDemo = std::filesystem::path(HAZE_SOURCE_DIR) / "examples/demo/demo.haze.json";

struct Demo {
  Show show;
  ProfileSet profiles;
};

Demo loadDemo() {
  auto show = loadShow(kDemo);
  EXPECT_TRUE(show.ok()) << show.error().str();
  auto profiles = loadProfiles(*show);
  EXPECT_TRUE(profiles.ok()) << profiles.error().str();
  return {std::move(*show), std::move(*profiles)};
}

// Every cue of the demo: the beams come from exactly the fixtures the state lights (read from
// the stage state here, not from the builder), each beam's dimmer is at most its fixture's
// intensity, and the facets of one fixture add up to its intensity.
TEST(FrameBuilder, DemoCuesGiveBeamsForExactlyTheLitFixtures) {
  const Demo d = loadDemo();
  ASSERT_FALSE(d.show.cueLists.empty());
  const CueList& list = d.show.cueLists.front();
  size_t checked = 0;
  for (size_t i = 0; i < list.cues.size(); ++i) {
    const StageState state = trackedState(d.show, d.profiles, list, i);
    auto frame = buildFrame(d.show, d.profiles, state, "");
    ASSERT_TRUE(frame.ok()) << frame.error().str();
    std::set<int> lit, beamed;
    std::map<int, float> dimmerSum;
    for (const auto& [id, a] : state)
      if (a.intensity * shutterMean(a.shutter) > 0.0f && a.cells.empty()) lit.insert(id);
    for (const BeamState& b : frame->beams) {
      beamed.insert(b.fixtureId);
      dimmerSum[b.fixtureId] += b.optics.dimmer;
      EXPECT_LE(b.optics.dimmer, state.at(b.fixtureId).intensity + 1e-6f);
    }
    for (int id : lit) {
      EXPECT_TRUE(beamed.count(id)) << "cue " << list.cues[i].number << ": fixture " << id << " is lit but has no beam";
      const Attributes& a = state.at(id);
      EXPECT_NEAR(dimmerSum[id], a.intensity * shutterMean(a.shutter), 1e-4f) << "cue " << list.cues[i].number;
    }
    for (int id : beamed) EXPECT_TRUE(lit.count(id)) << "cue " << list.cues[i].number << ": dark fixture " << id << " has a beam";
    checked += lit.size();
  }
  EXPECT_GT(checked, 0u) << "no cue of the demo lights anything: the test compared nothing";
}

// A fixture's beam leaves from its lens: the fixture's position plus the profile's lens offset
// turned by the head, so at pan 0 / tilt 0 the lens is within the offset's length of the fixture.
TEST(FrameBuilder, BeamsLeaveFromTheirFixtures) {
  Demo d = loadDemo();
  StageState state = defaultState(d.show);
  for (auto& [id, a] : state) a.intensity = 1.0f;
  auto frame = buildFrame(d.show, d.profiles, state, "");
  ASSERT_TRUE(frame.ok()) << frame.error().str();
  ASSERT_EQ(frame->beams.size() >= d.show.fixtures.size(), true);
  for (const BeamState& b : frame->beams) {
    const FixtureDef* f = d.show.findFixture(b.fixtureId);
    ASSERT_NE(f, nullptr);
    const Profile& p = *d.profiles.at(f->profile);
    EXPECT_LE(glm::length(b.pose.lensPosition - f->position), glm::length(p.lensOffset) + 1e-4f) << "fixture " << f->id;
    EXPECT_NEAR(glm::length(b.pose.zb), 1.0f, 1e-5f);
  }
}

// The keys: a dimmer or colour fade changes neither (no map is re-baked); a pan changes the pose
// key only; a zoom changes the optics key only.
TEST(FrameBuilder, CacheKeysFollowWhatTheMapsDependOn) {
  Demo d = loadDemo();
  StageState state = defaultState(d.show);
  const int id = d.show.fixtures.front().id;
  for (auto& [fid, a] : state) a.intensity = fid == id ? 1.0f : 0.0f;
  const auto keys = [&](const StageState& s) {
    auto frame = buildFrame(d.show, d.profiles, s, "");
    EXPECT_TRUE(frame.ok());
    EXPECT_FALSE(frame->beams.empty());
    return std::pair{frame->beams.front().poseKey, frame->beams.front().opticsKey};
  };
  const auto base = keys(state);
  StageState dimmer = state;
  dimmer[id].intensity = 0.3f;
  dimmer[id].color = {1.0f, 0.2f, 0.1f};
  EXPECT_EQ(keys(dimmer), base);
  StageState panned = state;
  panned[id].panDeg += 20.0f;
  EXPECT_NE(keys(panned).first, base.first);
  EXPECT_EQ(keys(panned).second, base.second);
  StageState zoomed = state;
  const Profile& p = *d.profiles.at(d.show.fixtures.front().profile);
  zoomed[id].zoomDeg = p.optics(state[id]).fieldAngleDeg * 0.5f;
  EXPECT_EQ(keys(zoomed).first, base.first);
  EXPECT_NE(keys(zoomed).second, base.second);
}

TEST(FrameBuilder, AnUnknownCameraIsAnErrorNamingTheShowsCameras) {
  const Demo d = loadDemo();
  auto frame = buildFrame(d.show, d.profiles, defaultState(d.show), "No such camera");
  ASSERT_FALSE(frame.ok());
  EXPECT_EQ(frame.error().place, "/cameras");
  ASSERT_FALSE(d.show.cameras.empty());
  EXPECT_NE(frame.error().message.find(d.show.cameras.front().name), std::string::npos) << frame.error().message;
}

BeamState cellBeam(glm::vec3 lens, float dimmer, glm::vec3 color, uint64_t opticsKey) {
  BeamState b;
  b.fixtureId = 7;
  b.pose.lensPosition = lens;
  b.optics.dimmer = dimmer;
  b.optics.color = color;
  b.optics.lensRadiusM = 0.05f;
  b.opticsKey = opticsKey;
  return b;
}

// docs/cells.md, "Cost": cells sharing a light map become one beam with the sum of their light,
// leaving from the light-weighted centre, its lens disc covering every cell's.
TEST(CellMerge, SharedOpticsBecomeOneBeamWithTheSumOfTheLight) {
  std::vector<BeamState> beams{cellBeam({0, 0, 0}, 1.0f, {1, 1, 1}, 1), cellBeam({0.3f, 0, 0}, 1.0f, {1, 0, 0}, 1),
                               cellBeam({9, 9, 9}, 0.5f, {0, 0, 1}, 2)};
  mergeCellBeams(beams);
  ASSERT_EQ(beams.size(), 2u);
  const BeamState& merged = beams[0].opticsKey == 1 ? beams[0] : beams[1];
  const BeamState& alone = beams[0].opticsKey == 1 ? beams[1] : beams[0];
  // Light: white 1 + red 1 = (2, 1, 1); weights 3 and 1 (r+g+b).
  EXPECT_NEAR(merged.optics.dimmer * merged.optics.color.r, 2.0f, 1e-5f);
  EXPECT_NEAR(merged.optics.dimmer * merged.optics.color.g, 1.0f, 1e-5f);
  EXPECT_NEAR(merged.optics.dimmer * merged.optics.color.b, 1.0f, 1e-5f);
  EXPECT_NEAR(merged.pose.lensPosition.x, 0.3f * 1.0f / 4.0f, 1e-6f);
  EXPECT_NEAR(merged.optics.lensRadiusM, 0.3f - 0.075f + 0.05f, 1e-6f);
  EXPECT_EQ(merged.cell, -1);
  EXPECT_EQ(merged.poseKey, poseCacheKey(merged.pose));
  EXPECT_FLOAT_EQ(alone.optics.dimmer, 0.5f);
  EXPECT_EQ(alone.pose.lensPosition, glm::vec3(9, 9, 9));
}

TEST(AtmosphereFrame, MediumAndUniformDensity) {
  AtmosphereDef def;
  def.phase = "isotropic";
  def.scattering = 0.02f;
  EXPECT_EQ(mediumState(def).phase, Phase::Isotropic);
  EXPECT_FLOAT_EQ(mediumState(def).scattering, 0.02f);
  def.phase = "hg";
  EXPECT_EQ(mediumState(def).phase, Phase::HenyeyGreenstein);
  // A show without a density spec has the uniform medium: no field, and nothing that moves.
  Demo d = loadDemo();
  d.show.atmosphere.density.reset();
  AtmosphereField field;
  std::vector<std::string> warnings;
  EXPECT_EQ(field.at(d.show, glm::vec3(-5), glm::vec3(5), 1.0, warnings), nullptr);
  EXPECT_FALSE(densityMoves(d.show.atmosphere));
  EXPECT_TRUE(warnings.empty());
}

// The demo's air variant has a density spec: the field exists, is simulated over the venue's
// box, and a frame built with it carries it to the renderer.
TEST(AtmosphereFrame, ADensitySpecGivesAFieldTheFrameCarries) {
  auto show = loadShow(std::filesystem::path(HAZE_SOURCE_DIR) / "examples/demo/air.haze.json");
  ASSERT_TRUE(show.ok()) << show.error().str();
  ASSERT_TRUE(show->atmosphere.density.has_value());
  auto profiles = loadProfiles(*show);
  ASSERT_TRUE(profiles.ok());
  AtmosphereField field;
  std::vector<std::string> warnings;
  auto density = field.at(*show, glm::vec3(-8, 0, -8), glm::vec3(8, 8, 8), 2.0, warnings);
  ASSERT_NE(density, nullptr);
  EXPECT_EQ(field.last(), density);
  auto frame = buildFrame(*show, *profiles, defaultState(*show), "", {.density = density});
  ASSERT_TRUE(frame.ok());
  EXPECT_EQ(frame->medium.density, density);
}

}  // namespace
}  // namespace haze
