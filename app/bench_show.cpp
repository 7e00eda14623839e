// A show's cue as the bench frame (see bench_show.h).
#include "app/bench_show.h"

#include <cstdio>

#include "shows/frame/atmosphere_field.h"
#include "shows/frame/frame_builder.h"
#include "shows/hazer_levels.h"
#include "shows/playback.h"
#include "shows/show.h"

namespace haze {

Status loadBenchShow(const Show& show, const ProfileSet& profiles, const std::string& cue,
                     const std::string& camera, CellBeams cells, Venue& venue, FrameState& frame, int& fixtures) {
  const std::string file = show.file.string();
  StageState state = defaultState(show);
  HazerSchedule hazers;
  if (const CueList* list = show.findCueList(""); list && !list->cues.empty()) {
    size_t index = 0;
    if (!cue.empty()) {
      auto found = findCue(*list, cue);
      if (!found) return Error{file, "/cue_lists/0", found.error().message};
      index = *found;
    }
    state = trackedState(show, profiles, *list, index);
    hazers = hazerSchedule(show, {{list, index}}, {});
  } else if (!cue.empty()) {
    return Error{file, "/cue_lists", "the show has no cues; --cue " + cue + " names none"};
  }
  if (!show.venueGltf.empty()) {
    auto v = loadVenue(show.resolve(show.venueGltf));
    if (!v) return v.error();
    venue = std::move(*v);
  }
  // The density field as a still of the cue shows it (at its GO).
  AtmosphereField atmosphere;
  std::vector<std::string> warnings;
  auto density = atmosphere.at(show, venue.boundsMin, venue.boundsMax, 0.0, warnings, hazers);
  for (const std::string& w : warnings) std::fprintf(stderr, "haze: warning: %s\n", w.c_str());
  auto f = buildFrame(show, profiles, state, camera, FrameOptions{.cells = cells, .density = std::move(density)});
  if (!f) return f.error();
  frame = std::move(*f);
  fixtures = static_cast<int>(show.fixtures.size());
  return Ok{};
}

}  // namespace haze
