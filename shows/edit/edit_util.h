// Small helpers the edit commands share (not for use outside shows/edit_*.cpp): user errors and
// finding fixtures and cues by what the GUI names them with.
#pragma once

#include <optional>
#include <string>

#include "fixtures/core/result.h"
#include "shows/show.h"

namespace haze::edit {

inline Error userError(std::string place, std::string message) { return Error{"", std::move(place), std::move(message)}; }

inline std::string fixturePlace(int id) { return "fixture " + std::to_string(id); }

// Index into Show::fixtures, or empty.
inline std::optional<size_t> fixtureIndex(const Show& show, int id) {
  for (size_t i = 0; i < show.fixtures.size(); ++i)
    if (show.fixtures[i].id == id) return i;
  return std::nullopt;
}

// Index into Show::cueLists ("" = the first list), or empty.
inline std::optional<size_t> listIndex(const Show& show, const std::string& name) {
  if (name.empty()) return show.cueLists.empty() ? std::nullopt : std::optional<size_t>(0);
  for (size_t i = 0; i < show.cueLists.size(); ++i)
    if (show.cueLists[i].name == name) return i;
  return std::nullopt;
}

inline std::string listPlace(const std::string& name) { return name.empty() ? std::string("the first cue list") : "cue list \"" + name + "\""; }
inline std::string cuePlace(const std::string& list, const std::string& number) {
  return "cue " + number + " of " + listPlace(list);
}

// The list and cue index of a cue, or an Error naming what is missing.
struct CueAt {
  size_t list = 0;
  size_t cue = 0;
};
Result<CueAt> findCueAt(const Show& show, const std::string& list, const std::string& number);

}  // namespace haze::edit
