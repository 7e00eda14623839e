// Names for imported fixtures that a designer can tell apart. CAD programs write the fixture
// type as every fixture's name (Vectorworks' theatre: 72 "Light Source Pendant 44deg"), so the
// name alone says nothing in a fixture list; the MVR's own numbers say which one it is.
#include <map>

#include "shows/import/mvr_import.h"

namespace haze {

namespace {

// "Clay Paky@Alpha Spot QWO 800@r3048" (a GDTF file's name: maker@type@revision) -> the type.
std::string typeName(const std::string& profileKey) {
  const auto first = profileKey.find('@');
  if (first == std::string::npos) return profileKey;
  const auto second = profileKey.find('@', first + 1);
  const std::string type = profileKey.substr(first + 1, second == std::string::npos ? std::string::npos : second - first - 1);
  return type.empty() ? profileKey : type;
}

// A UnitNumber of "0" or nothing is none (Vectorworks writes 0 for every fixture).
bool isUnit(const std::string& unit) { return !unit.empty() && unit.find_first_not_of('0') != std::string::npos; }

}  // namespace

std::vector<std::string> mvrFixtureNames(const std::vector<MvrFixtureLabel>& labels) {
  std::map<std::string, int> uses;
  for (const MvrFixtureLabel& l : labels) ++uses[l.name];
  std::vector<std::string> names;
  for (const MvrFixtureLabel& l : labels) {
    if (!l.name.empty() && uses[l.name] == 1) {
      names.push_back(l.name);
      continue;
    }
    const std::string base = l.name.empty() ? typeName(l.type) : l.name;
    if (!l.fixtureId.empty()) names.push_back(base + " " + l.fixtureId);
    else if (isUnit(l.unitNumber)) names.push_back(base + " unit " + l.unitNumber);
    else names.push_back(base + " " + std::to_string(l.id));
  }
  // Two fixtures with one FixtureID, or a composed name that is also another's own: the haze
  // id, unique in a show, sets each such pair apart.
  std::map<std::string, int> made;
  for (const std::string& n : names) ++made[n];
  for (std::size_t i = 0; i < names.size(); ++i)
    if (made[names[i]] > 1) names[i] += " #" + std::to_string(labels[i].id);
  return names;
}

bool isMvrComposedName(const std::string& name, const MvrFixtureLabel& label) {
  const std::string base = label.name.empty() ? typeName(label.type) : label.name;
  std::vector<std::string> forms = {base + " " + std::to_string(label.id)};
  if (!label.name.empty()) forms.push_back(label.name);
  if (!label.fixtureId.empty()) forms.push_back(base + " " + label.fixtureId);
  if (isUnit(label.unitNumber)) forms.push_back(base + " unit " + label.unitNumber);
  const std::string suffix = " #" + std::to_string(label.id);
  for (const std::string& f : forms)
    if (name == f || name == f + suffix) return true;
  return false;
}

}  // namespace haze
