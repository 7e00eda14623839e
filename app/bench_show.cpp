// A show's cue as the bench frame (see bench_show.h).
#include "app/bench_show.h"

#include "app/frame_builder.h"
#include "shows/playback.h"
#include "shows/show.h"

namespace haze {

Status loadBenchShow(const std::string& file, const std::string& cue, const std::string& camera, bool mergeCells,
                     Venue& venue, FrameState& frame, int& fixtures) {
  auto show = loadShow(file);
  if (!show) return show.error();
  auto profiles = loadProfiles(*show);
  if (!profiles) return profiles.error();
  StageState state = defaultState(*show);
  if (const CueList* list = show->findCueList(""); list && !list->cues.empty()) {
    size_t index = 0;
    if (!cue.empty()) {
      auto found = findCue(*list, cue);
      if (!found) return Error{file, "/cue_lists/0", found.error().message};
      index = *found;
    }
    state = trackedState(*show, *profiles, *list, index);
  } else if (!cue.empty()) {
    return Error{file, "/cue_lists", "the show has no cues; --cue " + cue + " names none"};
  }
  if (!show->venueGltf.empty()) {
    auto v = loadVenue(show->resolve(show->venueGltf));
    if (!v) return v.error();
    venue = std::move(*v);
  }
  auto f = buildFrame(*show, *profiles, state, camera, FrameOptions{.mergeCells = mergeCells});
  if (!f) return f.error();
  frame = std::move(*f);
  fixtures = static_cast<int>(show->fixtures.size());
  return Ok{};
}

}  // namespace haze
