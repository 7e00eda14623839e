// The rows of a fixture list (`haze fixture list`, the GUI's Fixtures and Patch tabs): one per
// fixture, sorted by id, with what a designer reads it by.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "shows/show.h"

namespace haze {

struct FixtureRow {
  int id = 0;
  std::string name, type, mode;
  std::optional<Patch> patch;   // nullopt: unpatched
  std::optional<int> channels;  // the mode's footprint; nullopt when the profile or mode is missing
};

// The fixture's type as a list shows it: its profile's maker and name ("Robe Robin 600E Spot"),
// the name alone when it already starts with the maker, else the show's profile key.
std::string fixtureTypeText(const FixtureDef& fixture, const ProfileSet& profiles);

// Every fixture of the show, sorted by id.
std::vector<FixtureRow> fixtureRows(const Show& show, const ProfileSet& profiles);

}  // namespace haze
