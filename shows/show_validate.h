// Show validation: every problem of a show at once, each with the file, a JSON pointer and one
// sentence. `haze validate` prints these; loadShow stops at the first structural one.
#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

#include "fixtures/core/result.h"
#include "shows/show.h"

namespace haze {

struct ProfileLoad {
  ProfileSet profiles;          // the ones that loaded
  std::vector<Error> problems;  // one per profile that did not, at /profiles/NAME
};

// Loads every profile the show names, collecting a problem for each that fails.
ProfileLoad loadProfilesAll(const Show& show);

// The checks that need profiles or compare parts of a show with each other: fixture ids unique,
// profiles known, modes known, DMX footprints within 512 and not overlapping, pan/tilt/zoom in
// the profile's ranges, gobo slots known, cue numbers increasing, cue values naming real
// fixtures, venue file present, camera names unique. Profiles missing from `profiles` (they
// failed to load, reported elsewhere) make the checks that need them skip quietly.
std::vector<Error> validateShow(const Show& show, const ProfileSet& profiles);

// A show read once and checked as `haze validate` checks it: the show and its profiles, usable
// only when `problems` is empty. Every command that reads a show goes through this, so what
// validate refuses every command refuses, with the same lines.
struct CheckedShow {
  Show show;
  ProfileSet profiles;
  std::vector<Error> problems;
};
CheckedShow checkShowFile(const std::filesystem::path& file);

// All of it for one file: read, parse, load profiles, validate. Empty means valid.
std::vector<Error> validateShowFile(const std::filesystem::path& file);
// The same for show text that is not (yet) on disk; `file` names it and anchors its paths.
std::vector<Error> validateShowText(std::string_view text, const std::filesystem::path& file);

}  // namespace haze
