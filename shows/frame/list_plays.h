// `--play LIST=CUE[@MASTER][+GO_S]` of `haze state` and `haze render` (docs/shows.md, "Several
// cue lists at once"): several cue lists played at once. Each named list stands in the cue
// before CUE (its full state, from time 0), its master at MASTER (default 1), and GOes into CUE
// GO_S seconds after time 0 (default 0). GOs at the same time happen in the order given, so the
// last --play of a moment wins the attributes both lists set. Follows fire as on stage.
#pragma once

#include <string>
#include <vector>

#include "fixtures/core/result.h"
#include "shows/hazer_levels.h"
#include "shows/playback.h"
#include "shows/show.h"

namespace haze {

struct ListPlay {
  std::string list, cue;
  double master = 1.0;
  double goAtS = 0.0;
};

// One --play value; the error says what was expected.
Result<ListPlay> parseListPlay(const std::string& text);

// The merged stage atS seconds after time 0 (real movement: the heads followed from rest on the
// stage at time 0). Errors name an unknown list (with the show's lists), an unknown cue, or a
// list played twice.
Result<StageState> playListsAt(const Show& show, const ProfileSet& profiles, const std::vector<ListPlay>& plays,
                               double atS, bool realMovement);

// The hazers' levels the plays give (docs/shows.md, "Hazers in cues"): with `timed`, each list's
// cue before CUE on stage from time 0 and a GO into CUE at GO_S; without, every CUE's full
// state. Plays naming an unknown list or cue add nothing (playListsAt says why).
HazerSchedule hazersOfPlays(const Show& show, const std::vector<ListPlay>& plays, bool timed);

// "Main cue 2, Specials cue 1 at master 0.5 GO at 2 s": for captions and image comments.
std::string describeListPlays(const std::vector<ListPlay>& plays);

}  // namespace haze
