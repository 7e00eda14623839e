// Names of imported fixtures (shows/import/mvr_import.h mvrFixtureNames): CAD programs write the
// type as every fixture's name; the list must still tell each fixture apart.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "shows/import/mvr_import.h"

namespace haze {
namespace {

TEST(MvrNames, AnOwnNameIsKept) {
  const std::vector<std::string> names =
      mvrFixtureNames({{.name = "FOH left", .fixtureId = "1", .unitNumber = "", .type = "T@Spot@r1", .id = 1},
                       {.name = "FOH right", .fixtureId = "2", .unitNumber = "", .type = "T@Spot@r1", .id = 2}});
  EXPECT_EQ(names, (std::vector<std::string>{"FOH left", "FOH right"}));
}

TEST(MvrNames, ASharedNameGetsTheFixtureIdElseTheUnitElseTheHazeId) {
  // Capture: FixtureID and UnitNumber; Vectorworks: FixtureID empty and UnitNumber 0 (none).
  const std::vector<std::string> names = mvrFixtureNames({
      {.name = "Alpha Spot", .fixtureId = "11", .unitNumber = "1", .type = "Clay Paky@Alpha Spot@r3", .id = 11},
      {.name = "Alpha Spot", .fixtureId = "12", .unitNumber = "2", .type = "Clay Paky@Alpha Spot@r3", .id = 12},
      {.name = "Pendant", .fixtureId = "", .unitNumber = "4", .type = "P", .id = 20},
      {.name = "Pendant", .fixtureId = "", .unitNumber = "5", .type = "P", .id = 21},
      {.name = "Pendant 44", .fixtureId = "", .unitNumber = "0", .type = "P", .id = 30},
      {.name = "Pendant 44", .fixtureId = "", .unitNumber = "", .type = "P", .id = 31},
  });
  EXPECT_EQ(names, (std::vector<std::string>{"Alpha Spot 11", "Alpha Spot 12", "Pendant unit 4", "Pendant unit 5", "Pendant 44 30",
                                             "Pendant 44 31"}));
}

TEST(MvrNames, NoNameIsTheTypeOfTheGdtfWithItsNumber) {
  const std::vector<std::string> names = mvrFixtureNames({{.name = "", .fixtureId = "", .unitNumber = "", .type = "Robe@Robin 600E Spot@2024", .id = 7},
                                                          {.name = "", .fixtureId = "", .unitNumber = "", .type = "plain_key", .id = 8}});
  EXPECT_EQ(names, (std::vector<std::string>{"Robin 600E Spot 7", "plain_key 8"}));
}

TEST(MvrNames, ARepeatedFixtureIdStillGivesDistinctNames) {
  const std::vector<MvrFixtureLabel> labels = {{.name = "Wash", .fixtureId = "5", .unitNumber = "", .type = "W", .id = 5},
                                               {.name = "Wash", .fixtureId = "5", .unitNumber = "", .type = "W", .id = 6},
                                               {.name = "Wash 5", .fixtureId = "", .unitNumber = "", .type = "W", .id = 7}};
  const std::vector<std::string> names = mvrFixtureNames(labels);
  EXPECT_EQ(names, (std::vector<std::string>{"Wash 5 #5", "Wash 5 #6", "Wash 5 #7"}));
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
}

TEST(MvrNames, AComposedNameIsRecognisedAsTheMvrsOwn) {
  const MvrFixtureLabel capture{.name = "Alpha Spot", .fixtureId = "11", .unitNumber = "1", .type = "Clay Paky@Alpha Spot@r3", .id = 11};
  EXPECT_TRUE(isMvrComposedName("Alpha Spot 11", capture));
  EXPECT_TRUE(isMvrComposedName("Alpha Spot 11 #11", capture));
  EXPECT_TRUE(isMvrComposedName("Alpha Spot", capture));
  EXPECT_FALSE(isMvrComposedName("Alpha Spot 12", capture));
  EXPECT_FALSE(isMvrComposedName("FOH 1", capture));  // renamed in haze: the export writes it
  const MvrFixtureLabel unnamed{.name = "", .fixtureId = "", .unitNumber = "0", .type = "Robe@Robin 600E Spot@2024", .id = 7};
  EXPECT_TRUE(isMvrComposedName("Robin 600E Spot 7", unnamed));
  EXPECT_FALSE(isMvrComposedName("Robin 600E Spot unit 0", unnamed));
}

}  // namespace
}  // namespace haze
