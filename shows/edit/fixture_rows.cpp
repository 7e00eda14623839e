// fixtureTypeText, fixtureRows (see fixture_rows.h).
#include "shows/edit/fixture_rows.h"

#include <algorithm>

#include "fixtures/profile.h"
#include "shows/edit/edit_commands.h"

namespace haze {

std::string fixtureTypeText(const FixtureDef& fixture, const ProfileSet& profiles) {
  const auto it = profiles.find(fixture.profile);
  if (it == profiles.end() || !it->second || it->second->name.empty()) return fixture.profile;
  const Profile& p = *it->second;
  if (p.manufacturer.empty() || p.name.rfind(p.manufacturer, 0) == 0) return p.name;
  return p.manufacturer + " " + p.name;
}

std::vector<FixtureRow> fixtureRows(const Show& show, const ProfileSet& profiles) {
  std::vector<FixtureRow> rows;
  for (const FixtureDef& f : show.fixtures) {
    FixtureRow r{.id = f.id, .name = f.name, .type = fixtureTypeText(f, profiles), .mode = f.mode, .patch = f.patch, .channels = {}};
    if (auto footprint = modeFootprint(profiles, f.profile, f.mode); footprint.ok()) r.channels = *footprint;
    rows.push_back(std::move(r));
  }
  std::stable_sort(rows.begin(), rows.end(), [](const FixtureRow& a, const FixtureRow& b) { return a.id < b.id; });
  return rows;
}

}  // namespace haze
