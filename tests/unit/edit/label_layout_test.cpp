// The viewport's label declutter and the fixture tabs' order and filter, without a window:
// labels of markers in a row, in one spot, or far apart never intersect, and only the ones
// that had to move get a leader line; the tabs list by id whatever the file order.
#include <gtest/gtest.h>

#include "shows/edit/label_layout.h"

namespace haze {
namespace {

void expectNoOverlap(const std::vector<PlacedLabel>& placed) {
  for (size_t i = 0; i < placed.size(); ++i)
    for (size_t j = i + 1; j < placed.size(); ++j)
      EXPECT_FALSE(placed[i].box.intersects(placed[j].box))
          << "labels of " << placed[i].fixture << " and " << placed[j].fixture << " overlap";
}

TEST(LabelLayout, SixMarkersInARowStackWithoutOverlap) {
  // Six spots 30 px apart on a truss: each 90x14 label would run over the next three.
  std::vector<LabelRequest> row;
  for (int i = 0; i < 6; ++i) row.push_back({.fixture = 101 + i, .anchor = {100.0f + 30.0f * i, 200.0f}, .sizePx = {90, 14}});
  const auto placed = placeLabels(row);
  ASSERT_EQ(placed.size(), 6u);
  expectNoOverlap(placed);
  EXPECT_FALSE(placed[0].moved);  // the first keeps its place beside its marker
  EXPECT_EQ(placed[0].box.x, 111.0f);
  EXPECT_EQ(placed[0].box.y, 193.0f);
  int moved = 0;
  for (size_t i = 1; i < placed.size(); ++i) {
    EXPECT_EQ(placed[i].box.x, row[i].anchor.x + 11.0f);  // pushed down only, never sideways
    EXPECT_EQ(placed[i].moved, placed[i].box.y > 193.0f) << placed[i].fixture;
    // Moved only when its own place beside the marker met a label placed before it.
    LabelBox first = placed[i].box;
    first.y = 193.0f;
    bool met = false;
    for (size_t j = 0; j < i; ++j) met = met || first.intersects(placed[j].box);
    EXPECT_EQ(placed[i].moved, met) << placed[i].fixture;
    moved += placed[i].moved;
  }
  // 102, 103, 105 and 106 meet a label before them; 104 starts where 101's ends (90 px on).
  EXPECT_EQ(moved, 4);
  EXPECT_FALSE(placed[3].moved);
}

TEST(LabelLayout, FarApartLabelsStayPut) {
  const auto placed = placeLabels({{.fixture = 1, .anchor = {10, 10}, .sizePx = {50, 12}},
                                   {.fixture = 2, .anchor = {300, 10}, .sizePx = {50, 12}},
                                   {.fixture = 3, .anchor = {10, 300}, .sizePx = {50, 12}}});
  for (const PlacedLabel& p : placed) EXPECT_FALSE(p.moved) << p.fixture;
  expectNoOverlap(placed);
}

TEST(LabelLayout, ManyAtOnePointStillNeverOverlap) {
  std::vector<LabelRequest> pile;
  for (int i = 0; i < 30; ++i) pile.push_back({.fixture = i, .anchor = {50, 50}, .sizePx = {40.0f + i, 13}});
  expectNoOverlap(placeLabels(pile));
}

TEST(LabelLayout, BeyondTheLimitALabelKeepsItsPlace) {
  const auto placed = placeLabels({{.fixture = 1, .anchor = {0, 0}, .sizePx = {50, 12}},
                                   {.fixture = 2, .anchor = {0, 0}, .sizePx = {50, 12}}},
                                  5.0f);
  EXPECT_FALSE(placed[1].moved);
  EXPECT_TRUE(placed[0].box.intersects(placed[1].box));
}

Show threeFixtures() {
  Show show;
  show.fixtures.push_back({.id = 301, .name = "Beam 1", .profile = "beam", .mode = "Std", .patch = Patch{3, 1}});
  show.fixtures.push_back({.id = 101, .name = "Spot 1", .profile = "spot", .mode = "Standard", .patch = Patch{1, 1}});
  show.fixtures.push_back({.id = 201, .name = "Wash 1", .profile = "wash", .mode = "", .patch = std::nullopt});
  return show;
}

std::vector<int> ids(const std::vector<const FixtureDef*>& fs) {
  std::vector<int> out;
  for (const FixtureDef* f : fs) out.push_back(f->id);
  return out;
}

TEST(FixtureTabs, SortedByIdWhateverTheFileOrder) {
  EXPECT_EQ(ids(listedFixtures(threeFixtures(), "")), (std::vector<int>{101, 201, 301}));
  EXPECT_EQ(ids(listedFixtures(threeFixtures(), "  ")), (std::vector<int>{101, 201, 301}));
}

TEST(FixtureTabs, FilterMatchesIdNameProfileAndPatch) {
  const Show show = threeFixtures();
  EXPECT_EQ(ids(listedFixtures(show, "spot")), (std::vector<int>{101}));  // name and profile, any case
  EXPECT_EQ(ids(listedFixtures(show, " WASH ")), (std::vector<int>{201}));
  EXPECT_EQ(ids(listedFixtures(show, "3.1")), (std::vector<int>{301}));   // universe.address
  EXPECT_EQ(ids(listedFixtures(show, "01")), (std::vector<int>{101, 201, 301}));
  EXPECT_TRUE(listedFixtures(show, "Profile XL").empty());
  EXPECT_EQ(patchText(show.fixtures[0]), "3.1");
  EXPECT_EQ(patchText(show.fixtures[2]), "-");
}

}  // namespace
}  // namespace haze
