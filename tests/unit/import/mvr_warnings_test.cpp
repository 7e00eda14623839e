// Folding an MVR import's warnings into kinds (groupMvrWarnings): built lists whose kinds are
// known, and the Capture demo show, whose stub GDTFs repeat one warning for every channel.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "shows/import/mvr_import.h"
#include "unit/gdtf/zip_builder.h"
#include "test_data.h"

namespace haze {
namespace {

TEST(MvrWarnings, SameSentenceDifferentNamesAndPlacesIsOneKind) {
  const std::vector<std::string> in = {
      "a.gdtf: description.xml line 58 <DMXChannel>: attribute 'Dimmer1' is not used by haze; its channel is read past",
      "GeneralSceneDescription.xml line 372 <CustomCommands>: <CustomCommands> of fixtures is not used by haze; ignored",
      "b.gdtf: description.xml line 91 <DMXChannel>: attribute 'Dimmer10' is not used by haze; its channel is read past",
      "GeneralSceneDescription.xml line 386 <Color>: <Color> (the fixture's colour in drawings) is not a light colour in haze; ignored",
      "a.gdtf: description.xml line 60 <DMXChannel>: attribute 'Dimmer2' is not used by haze; its channel is read past",
  };
  const auto out = groupMvrWarnings(in);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[0], in[0] + " (and 2 more like it)");  // the first one in full, with the count
  EXPECT_EQ(out[1], in[1]);                             // once: unchanged
  EXPECT_EQ(out[2], in[3]);
}

TEST(MvrWarnings, DifferentSentencesStaySeparate) {
  const std::vector<std::string> in = {
      "GeneralSceneDescription.xml line 8 <Fixture name=\"A\">: GDTFSpec \"x.gdtf\" is not in the archive; fixtures of this type are left out",
      "GeneralSceneDescription.xml line 9 <Fixture name=\"B\">: FixtureID 3 is used twice; this fixture gets a new id",
      "GeneralSceneDescription.xml line 10 <Fixture name=\"C\">: FixtureID 4 is used twice; this fixture gets a new id",
  };
  const auto out = groupMvrWarnings(in);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0], in[0]);
  EXPECT_EQ(out[1], in[1] + " (and 1 more like it)");
  EXPECT_TRUE(groupMvrWarnings({}).empty());
}

// The Capture export: its warnings fold into a handful of lines, and the counts in
// the folded lines add up to every warning.
TEST(MvrWarnings, CaptureDemoShowFoldsIntoAFewLines) {
  HAZE_NEED_DATA("gdtf/mvr/capture_demo_show.mvr");
  test::TempDir dir("mvrwarn");
  auto r = importMvr(test::dataFile("gdtf/mvr/capture_demo_show.mvr"), dir / "c.haze.json");
  ASSERT_TRUE(r.ok()) << r.error().str();
  // Its stub GDTFs' Dimmer1..n channels are read as dimmers (docs/live.md), so they no longer
  // give a warning per channel; what is left still folds, and adds up.
  ASSERT_GT(r->warnings.size(), 0u);
  for (const std::string& w : r->warnings) EXPECT_EQ(w.find("'Dimmer"), std::string::npos) << w;
  const auto out = groupMvrWarnings(r->warnings);
  EXPECT_LE(out.size(), 10u);
  std::size_t total = 0;
  for (const std::string& line : out) {
    total += 1;
    const auto more = line.rfind(" (and ");
    if (more != std::string::npos) total += std::strtoul(line.c_str() + more + 6, nullptr, 10);
  }
  EXPECT_EQ(total, r->warnings.size());
}

}  // namespace
}  // namespace haze
