// The designer's path through the GUI's document, without a window, on the real demo show:
// click the truss, place a spot there (it hangs under the truss), bring it up, focus it on the
// set's sphere (the beam axis passes within 1 cm of the point), record a cue (only what
// changed), undo everything back to the show as loaded and redo it, save, reopen, and find the
// same fixture and cue, still hitting the sphere. Also: profiles from files, playback, guards.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <glm/geometric.hpp>

#include "shows/edit/recent_files.h"
#include "shows/edit/show_document.h"
#include "fixtures/pose.h"
#include "shows/show_json.h"
#include "test_data.h"

namespace haze {
namespace {

namespace fs = std::filesystem;

const fs::path kDemo = fs::path(HAZE_SOURCE_DIR) / "examples/demo/demo.haze.json";
const glm::vec3 kSphereM{0.9f, 1.55f, -1.8f};  // the set's sphere (venue node "sphere")

fs::path scratchDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("haze-gui-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// Distance from a point to the beam axis (ahead of the lens) of a fixture at its stage state.
float axisMissM(const ShowDocument& doc, int id, const Attributes& a, const glm::vec3& p) {
  const FixtureDef* f = doc.show().findFixture(id);
  const BeamPose pose = beamPose(f->position, f->rotationDeg, a.panDeg, a.tiltDeg, doc.profiles().at(f->profile)->lensOffset);
  const glm::vec3 d = glm::normalize(pose.zb);
  const glm::vec3 v = p - pose.lensPosition;
  EXPECT_GT(glm::dot(v, d), 0.0f) << "the point is behind the lens";
  return glm::length(v - glm::dot(v, d) * d);
}

CameraState foh(const ShowDocument& doc) {
  CameraState c;
  const CameraDef& def = doc.show().cameras.front();
  c.position = def.position;
  c.target = def.target;
  c.fovYDeg = def.fovYDeg;
  return c;
}

TEST(ShowDocument, PlaceFocusRecordUndoSaveReopen) {
  auto opened = ShowDocument::open(kDemo);
  ASSERT_TRUE(opened) << opened.error().str();
  ShowDocument& doc = **opened;
  const std::string asLoaded = showToText(doc.show());
  EXPECT_FALSE(doc.modified());
  EXPECT_EQ(doc.title(), "haze - demo.haze.json");

  // A click a few pixels off the truss's front bottom chord, in the FOH view of the GUI's test
  // window (a 250 x 341 viewport): the snap finds the truss, and the spot hangs from its underside.
  const ViewCamera view(foh(doc), {250.0f, 341.0f});
  const auto onTruss = view.project({0.5f, 8.025f, -2.875f});
  ASSERT_TRUE(onTruss);
  const auto hit = pickVenue(doc.bvh(), view, *onTruss + glm::vec2(0.0f, 3.0f), 6.0f);
  ASSERT_TRUE(hit);
  EXPECT_LT(hit->distanceM, 14.5f) << "hit something behind the truss";
  const MountPose pose = mountOnSurface(*hit);
  EXPECT_EQ(pose.kind, MountPose::Kind::Hanging);
  EXPECT_NEAR(pose.positionM.y, 8.0f, 0.02f);  // the chords' underside, where the demo's spots hang
  EXPECT_NEAR(pose.positionM.z, -3.0f, 0.2f);
  EXPECT_NEAR(pose.positionM.x, 0.5f, 0.2f);

  auto id = doc.placeFixtureAt("spot", pose);
  ASSERT_TRUE(id) << id.error().str();
  EXPECT_EQ(*id, 305);
  EXPECT_EQ(doc.selection, std::vector<int>{305});
  ASSERT_TRUE(doc.show().findFixture(305)->patch);
  EXPECT_EQ(doc.show().findFixture(305)->patch->address, 49);  // the first 12-slot gap: spots take 1..48
  EXPECT_TRUE(doc.modified());
  EXPECT_EQ(doc.title(), "haze - demo.haze.json *");

  ASSERT_TRUE(doc.setSelectionValues(CueValues{.intensity = 1.0f}, false));
  auto focused = doc.focusSelectionOn(kSphereM, doc.stageState(0.0));
  ASSERT_TRUE(focused) << focused.error().str();
  ASSERT_EQ(focused->size(), 1u);
  EXPECT_TRUE(focused->front().reached);
  StageState stage = doc.stageState(0.0);
  EXPECT_LT(axisMissM(doc, 305, stage.at(305), kSphereM), 0.01f);

  const size_t cuesBefore = doc.cueList()->cues.size();
  auto number = doc.recordCue("", "Sphere special");
  ASSERT_TRUE(number) << number.error().str();
  EXPECT_EQ(*number, "6");  // after the demo's last cue, 5
  const Cue& cue = doc.cueList()->cues.back();
  EXPECT_EQ(cue.label, "Sphere special");
  ASSERT_EQ(cue.values.size(), 1u);  // tracking: only the new fixture changed
  const CueValues& v = cue.values.at(305);
  EXPECT_EQ(v.intensity, 1.0f);
  EXPECT_TRUE(v.panDeg && v.tiltDeg);
  EXPECT_FALSE(v.color);  // never set, so not recorded
  const std::string afterEdits = showToText(doc.show());

  // Undo all the way back to the show as loaded, then redo to the end.
  int steps = 0;
  while (doc.undo()) ++steps;
  EXPECT_EQ(steps, 4);  // place, intensity, focus, record
  EXPECT_EQ(showToText(doc.show()), asLoaded);
  EXPECT_TRUE(doc.programmer().values.empty());
  EXPECT_FALSE(doc.modified());
  EXPECT_EQ(doc.cueList()->cues.size(), cuesBefore);
  while (doc.redo()) --steps;
  EXPECT_EQ(steps, 0);
  EXPECT_EQ(showToText(doc.show()), afterEdits);

  const fs::path dir = scratchDir("walk");
  const fs::path file = dir / "walk.haze.json";
  ASSERT_TRUE(doc.save(file)) << "save";
  EXPECT_FALSE(doc.modified());
  EXPECT_EQ(doc.title(), "haze - walk.haze.json");

  auto again = ShowDocument::open(file);
  ASSERT_TRUE(again) << again.error().str();
  ShowDocument& re = **again;
  const FixtureDef* f = re.show().findFixture(305);
  ASSERT_TRUE(f);
  EXPECT_NEAR(glm::length(f->position - pose.positionM), 0.0f, 1e-4f);
  ASSERT_EQ(re.cueList()->cues.size(), cuesBefore + 1);
  EXPECT_EQ(re.cueList()->cues.back().label, "Sphere special");
  ASSERT_TRUE(re.jumpTo(re.cueList()->cues.size() - 1, 0.0));
  stage = re.stageState(0.0);
  EXPECT_EQ(stage.at(305).intensity, 1.0f);
  EXPECT_LT(axisMissM(re, 305, stage.at(305), kSphereM), 0.01f);
  fs::remove_all(dir);
}

TEST(ShowDocument, FocusOutOfReachGivesTheNearestDirection) {
  auto opened = ShowDocument::open(kDemo);
  ASSERT_TRUE(opened);
  ShowDocument& doc = **opened;
  // A floor beam stands on the deck pointing up; the spot's tilt reaches 135 degrees but the
  // beam profile's range is checked by focusOnPoint: a point straight below it needs tilt 180.
  doc.selection = {301};
  const FixtureDef* f = doc.show().findFixture(301);
  auto r = doc.focusSelectionOn(f->position - glm::vec3(0.0f, 5.0f, 0.0f), doc.stageState(0.0));
  ASSERT_TRUE(r);
  ASSERT_EQ(r->size(), 1u);
  EXPECT_FALSE(r->front().reached);
  EXPECT_FALSE(r->front().note.empty());
  // The programmer holds the nearest reachable direction, within the profile's ranges.
  const CueValues& v = doc.programmer().values.at(301);
  const Profile& p = *doc.profiles().at(f->profile);
  EXPECT_TRUE(p.tiltDeg.contains(*v.tiltDeg));
  EXPECT_TRUE(p.panDeg.contains(*v.panDeg));
  // No selection: an error, nothing changes.
  doc.selection.clear();
  const size_t steps = doc.history().undoSteps();
  EXPECT_FALSE(doc.focusSelectionOn(glm::vec3(0.0f), doc.stageState(0.0)));
  EXPECT_EQ(doc.history().undoSteps(), steps);
}

TEST(ShowDocument, AimingByDragIsOneUndoStep) {
  auto opened = ShowDocument::open(kDemo);
  ASSERT_TRUE(opened);
  ShowDocument& doc = **opened;
  doc.selection = {101, 104};
  // The beam's end dragged across the deck: a focus per frame, merged into the first.
  for (int i = 0; i < 5; ++i)
    ASSERT_TRUE(doc.focusSelectionOn(glm::vec3(-2.0f + static_cast<float>(i), 1.0f, -3.0f), doc.stageState(0.0), i > 0));
  EXPECT_EQ(doc.history().undoSteps(), 1u);
  const StageState s = doc.stageState(0.0);
  for (int id : {101, 104}) EXPECT_LT(axisMissM(doc, id, s.at(id), glm::vec3(2.0f, 1.0f, -3.0f)), 0.01f) << id;
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(doc.programmer().values.empty());
}

TEST(ShowDocument, MultiSelectionSetsEveryFixtureInOneStep) {
  auto opened = ShowDocument::open(kDemo);
  ASSERT_TRUE(opened);
  ShowDocument& doc = **opened;
  doc.selection = {101, 102, 201};
  ASSERT_TRUE(doc.setSelectionValues(CueValues{.color = glm::vec3(1.0f, 0.0f, 0.0f)}, false));
  ASSERT_TRUE(doc.setSelectionValues(CueValues{.color = glm::vec3(0.0f, 1.0f, 0.0f)}, true));  // same drag
  EXPECT_EQ(doc.history().undoSteps(), 1u);
  const StageState s = doc.stageState(0.0);
  for (int id : {101, 102, 201}) EXPECT_EQ(s.at(id).color, glm::vec3(0.0f, 1.0f, 0.0f)) << id;
  EXPECT_NE(s.at(103).color, glm::vec3(0.0f, 1.0f, 0.0f));
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(doc.programmer().values.empty());
}

TEST(ShowDocument, PlaybackGoBackGotoAndFadeProgress) {
  auto opened = ShowDocument::open(kDemo);
  ASSERT_TRUE(opened);
  ShowDocument& doc = **opened;
  EXPECT_FALSE(doc.currentCue());
  ASSERT_TRUE(doc.go(10.0));  // cue 1: fade 5 s
  EXPECT_EQ(doc.currentCue(), 0u);
  EXPECT_NEAR(doc.fadeProgress(12.5), 0.5, 1e-9);
  EXPECT_TRUE(doc.fading(12.5));
  EXPECT_EQ(doc.fadeProgress(20.0), 1.0);
  ASSERT_TRUE(doc.go(20.0));   // cue 2
  ASSERT_TRUE(doc.back(30.0)); // cue 1 with its own times
  EXPECT_EQ(doc.currentCue(), 0u);
  ASSERT_TRUE(doc.gotoCue(2, 40.0));  // cue 3: delay 2 s, fade 8 s
  EXPECT_EQ(doc.fadeProgress(41.0), -1.0);
  EXPECT_NEAR(doc.fadeProgress(46.0), 0.5, 1e-9);
  // The programmer (or a fixture's move) leaves the fade running...
  doc.selection = {101};
  ASSERT_TRUE(doc.setSelectionValues(CueValues{.intensity = 0.5f}, false));
  ASSERT_TRUE(doc.run(moveFixture(102, glm::vec3(0.0f, 8.0f, -3.0f))));
  EXPECT_EQ(doc.currentCue(), 2u);
  EXPECT_NEAR(doc.fadeProgress(46.0), 0.5, 1e-9);
  EXPECT_EQ(doc.stageState(46.0).at(101).intensity, 0.5f);  // the programmer wins over playback
  // ...an edit of the cues puts the player back on the same cue, in full.
  ASSERT_TRUE(doc.run(labelCue("", "3", "Renamed")));
  EXPECT_EQ(doc.currentCue(), 2u);
  EXPECT_EQ(doc.fadeProgress(46.0), 1.0);
  EXPECT_FALSE(doc.fading(46.0));
}

// The Playback tab's model: a second list GOes beside the first, its master scales its
// intensity, and an edit of the cues keeps every list on its cue, its master and the order of
// their GOs (values from tests/data/shows/playbacks.haze.json, worked out in docs/shows.md).
TEST(ShowDocument, SeveralListsPlayAtOnce) {
  auto opened = ShowDocument::open(fs::path(HAZE_SOURCE_DIR) / "tests/data/shows/playbacks.haze.json");
  ASSERT_TRUE(opened) << opened.error().str();
  ShowDocument& doc = **opened;
  ASSERT_EQ(doc.listCount(), 2u);
  ASSERT_TRUE(doc.go(0.0));             // Main cue 1: 1 at 0.6 pan 30, 2 at 0.2
  ASSERT_TRUE(doc.listGo(1, 1.0));      // Specials cue 1, fade 2: 1 at 0.5 pan 90, 2 at 0.8
  EXPECT_NEAR(doc.listFadeProgress(1, 2.0), 0.5, 1e-9);
  EXPECT_FLOAT_EQ(doc.stageState(2.0).at(2).intensity, 0.4f);  // max(0.2, 0.4)
  StageState s = doc.stageState(3.0);
  EXPECT_FLOAT_EQ(s.at(1).intensity, 0.6f);
  EXPECT_FLOAT_EQ(s.at(2).intensity, 0.8f);
  EXPECT_FLOAT_EQ(s.at(1).panDeg, 90.0f);
  doc.setListMaster(1, 0.5);
  EXPECT_FLOAT_EQ(doc.stageState(3.0).at(2).intensity, 0.4f);  // max(0.2, 0.5 x 0.8)
  ASSERT_TRUE(doc.run(labelCue("Main", "1", "Renamed")));
  EXPECT_EQ(doc.listCue(0), 0u);
  EXPECT_EQ(doc.listCue(1), 0u);
  EXPECT_EQ(doc.listMaster(1), 0.5);
  s = doc.stageState(4.0);
  EXPECT_FLOAT_EQ(s.at(2).intensity, 0.4f);
  EXPECT_FLOAT_EQ(s.at(1).panDeg, 90.0f);  // Specials GOed last, and still holds pan
  EXPECT_FALSE(doc.listBack(1, 5.0));      // nothing before its cue 1
  EXPECT_FALSE(doc.listGo(7, 5.0));        // no such list
}

TEST(ShowDocument, ProfilesFromFilesJoinTheLibrary) {
  auto opened = ShowDocument::open(kDemo);
  ASSERT_TRUE(opened);
  ShowDocument& doc = **opened;
  const fs::path ies = test::dataFile("photometry/ies/hydraapi/ies_4.ies");
  auto key = doc.addProfileFile(ies);
  ASSERT_TRUE(key) << key.error().str();
  EXPECT_EQ(*key, "ies-4");
  EXPECT_TRUE(doc.modified());
  // Named relative to the show, so the saved show finds it from its own folder.
  EXPECT_FALSE(fs::path(doc.show().profiles.at(*key).path).is_absolute());
  EXPECT_TRUE(fs::exists(doc.show().resolve(doc.show().profiles.at(*key).path)));
  auto again = doc.addProfileFile(ies);
  ASSERT_TRUE(again);
  EXPECT_EQ(*again, "ies-4-2");
  // Patched when the profile has a DMX mode, unpatched when it has none.
  auto id = doc.placeFixtureAt(*key, MountPose{.positionM = {0.0f, 8.0f, -3.0f}});
  ASSERT_TRUE(id) << id.error().str();
  EXPECT_EQ(doc.show().findFixture(*id)->patch.has_value(), !doc.profiles().at(*key)->modes.empty());
  // A file that is not a profile: an error naming it, the library unchanged.
  const size_t n = doc.profiles().size();
  auto bad = doc.addProfileFile(kDemo.parent_path() / "venue/theatre.gltf");
  EXPECT_FALSE(bad);
  EXPECT_EQ(doc.profiles().size(), n);
}

TEST(ShowDocument, AddingAProfileIsOneUndoStep) {
  auto opened = ShowDocument::open(kDemo);
  ASSERT_TRUE(opened);
  ShowDocument& doc = **opened;
  const std::string original = showToText(doc.show());
  const size_t profiles = doc.profiles().size();
  auto key = doc.addProfileFile(test::dataFile("photometry/ies/hydraapi/ies_4.ies"));
  ASSERT_TRUE(key) << key.error().str();
  EXPECT_EQ(doc.history().undoLabel(), "Add profile " + *key);
  auto id = doc.placeFixtureAt(*key, MountPose{.positionM = {0.0f, 8.0f, -3.0f}});
  ASSERT_TRUE(id) << id.error().str();
  // Undo the placing, then the adding: the library and the show as loaded, nothing unsaved.
  ASSERT_TRUE(doc.undo());
  ASSERT_TRUE(doc.undo());
  EXPECT_FALSE(doc.profiles().count(*key));
  EXPECT_EQ(doc.profiles().size(), profiles);
  EXPECT_EQ(showToText(doc.show()), original);
  EXPECT_FALSE(doc.modified());
  // Redo both: the profile is back and the fixture of it too.
  ASSERT_TRUE(doc.redo());
  ASSERT_TRUE(doc.profiles().count(*key));
  ASSERT_TRUE(doc.redo());
  ASSERT_TRUE(doc.show().findFixture(*id));
  EXPECT_EQ(doc.show().findFixture(*id)->profile, *key);
  EXPECT_TRUE(doc.modified());
}

TEST(ShowDocument, NewShowKeepsTheVenueAndNeedsAPathToSave) {
  auto opened = ShowDocument::open(kDemo);
  ASSERT_TRUE(opened);
  auto blank = ShowDocument::blank(opened->get());
  ASSERT_TRUE(blank);
  ShowDocument& doc = **blank;
  EXPECT_TRUE(doc.untitled());
  EXPECT_TRUE(doc.show().fixtures.empty());
  EXPECT_EQ(doc.venue().primitives.size(), (*opened)->venue().primitives.size());
  EXPECT_EQ(doc.title(), "haze - untitled");
  EXPECT_FALSE(doc.save());  // no file yet: Save as
  const fs::path dir = scratchDir("new");
  ASSERT_TRUE(doc.addProfileFile(kDemo.parent_path() / "profiles/profile-spot.json"));
  ASSERT_TRUE(doc.placeFixtureAt("profile-spot", MountPose{.positionM = {0.0f, 8.0f, -3.0f}}));
  ASSERT_TRUE(doc.save(dir / "new.haze.json"));
  auto re = ShowDocument::open(dir / "new.haze.json");
  ASSERT_TRUE(re) << re.error().str();
  EXPECT_EQ((*re)->show().fixtures.size(), 1u);
  EXPECT_EQ((*re)->venue().primitives.size(), (*opened)->venue().primitives.size());
  fs::remove_all(dir);
}

TEST(ShowDocument, AnEmptyStageHasNothingToHit) {
  auto blank = ShowDocument::blank(nullptr);
  ASSERT_TRUE(blank);
  EXPECT_EQ((*blank)->bvh().triangleCount(), 0u);
  EXPECT_FALSE(castVenue((*blank)->bvh(), Ray{{0.0f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}}));
  EXPECT_FALSE((*blank)->go(0.0));  // no cues
  EXPECT_EQ((*blank)->fadeProgress(0.0), 1.0);
}

TEST(ShowDocument, PatchConflictsAreOverlapsAndOverruns) {
  auto opened = ShowDocument::open(kDemo);
  ASSERT_TRUE(opened);
  Show show = (*opened)->show();  // a copy to break by hand (the commands refuse overlaps)
  EXPECT_TRUE(patchConflicts(show, (*opened)->profiles()).empty());
  // Spot 2 (12 slots) moved to 20: 20..31 misses Spot 1 (1..12) and hits Spot 3 (25..36).
  for (FixtureDef& f : show.fixtures) {
    if (f.id == 102) f.patch->address = 20;
    if (f.id == 304) f.patch->address = 510;  // a beam of 8 slots: 510..517, past 512
    if (f.id == 201) f.patch->universe = 2;   // alone in universe 2
  }
  EXPECT_EQ(patchConflicts(show, (*opened)->profiles()), (std::set<int>{102, 103, 304}));
}

TEST(RecentFiles, NewestFirstUniqueBoundedAndKept) {
  const fs::path dir = scratchDir("recent");
  const fs::path list = dir / "haze/recent.txt";
  EXPECT_TRUE(loadRecentFiles(list).empty());  // no file: no list
  std::vector<std::string> r;
  for (int i = 0; i < 12; ++i) r = withRecentFile(r, dir / ("s" + std::to_string(i) + ".haze.json"));
  r = withRecentFile(r, dir / "s5.haze.json");
  ASSERT_EQ(r.size(), kMaxRecentFiles);
  EXPECT_EQ(r.front(), (dir / "s5.haze.json").string());
  EXPECT_EQ(r[1], (dir / "s11.haze.json").string());
  EXPECT_EQ(std::count(r.begin(), r.end(), (dir / "s5.haze.json").string()), 1);
  ASSERT_TRUE(saveRecentFiles(list, r));
  EXPECT_EQ(loadRecentFiles(list), r);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace haze
