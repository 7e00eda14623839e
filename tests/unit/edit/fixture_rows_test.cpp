// The rows of a fixture list (shows/edit/fixture_rows.h): by id whatever the file order, with
// type, mode, patch and footprint.
#include <gtest/gtest.h>

#include <memory>

#include "fixtures/profile.h"
#include "shows/edit/fixture_rows.h"

namespace haze {
namespace {

std::shared_ptr<Profile> profile(const std::string& maker, const std::string& name, int channels) {
  auto p = std::make_shared<Profile>();
  p->manufacturer = maker;
  p->name = name;
  DmxMode m;
  m.name = "Std";
  m.channels.resize(static_cast<size_t>(channels));
  p->modes.push_back(m);
  return p;
}

TEST(FixtureRows, SortedByIdWithTypeModePatchAndFootprint) {
  Show show;
  show.fixtures.push_back({.id = 30, .name = "Beam 1", .profile = "beam", .mode = "Std", .patch = Patch{3, 101}});
  show.fixtures.push_back({.id = 4, .name = "Spot 1", .profile = "spot", .mode = "Std", .patch = Patch{1, 1}});
  show.fixtures.push_back({.id = 12, .name = "Gone", .profile = "missing", .mode = "Std", .patch = std::nullopt});
  ProfileSet profiles;
  profiles["beam"] = profile("Clay Paky", "Clay Paky Sharpy", 16);  // the name starts with the maker
  profiles["spot"] = profile("Robe", "Robin 600E Spot", 24);
  const std::vector<FixtureRow> rows = fixtureRows(show, profiles);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].id, 4);
  EXPECT_EQ(rows[1].id, 12);
  EXPECT_EQ(rows[2].id, 30);
  EXPECT_EQ(rows[0].type, "Robe Robin 600E Spot");
  EXPECT_EQ(rows[2].type, "Clay Paky Sharpy");
  EXPECT_EQ(rows[1].type, "missing");  // no profile loaded: the show's key
  EXPECT_EQ(rows[0].channels, 24);
  EXPECT_FALSE(rows[1].channels.has_value());
  ASSERT_TRUE(rows[2].patch.has_value());
  EXPECT_EQ(rows[2].patch->universe, 3);
  EXPECT_EQ(rows[2].patch->address, 101);
  EXPECT_FALSE(rows[1].patch.has_value());
  EXPECT_EQ(rows[0].name, "Spot 1");
  EXPECT_EQ(rows[0].mode, "Std");
}

}  // namespace
}  // namespace haze
