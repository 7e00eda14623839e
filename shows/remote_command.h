// What a console or a remote says to the live cue engine (shows/frame/live_playback.h): GO,
// BACK, GOTO, a fixture's attribute over playback, a camera, a list's GO or master. The OSC
// decoder (shows/dmx/osc_command.h) produces these; the cue engine consumes them; neither knows
// the other.
#pragma once

#include <string>

#include "shows/show.h"

namespace haze {

struct RemoteCommand {
  enum class Kind { Go, Back, Goto, SetFixture, ClearFixture, ClearAll, Camera, ListGo, ListBack, ListMaster };
  Kind kind = Kind::Go;
  std::string cue;      // Goto
  std::string camera;   // Camera: the camera's name
  std::string list;     // ListGo, ListBack, ListMaster: the cue list's name
  double level = 1.0;   // ListMaster
  int fixture = 0;      // SetFixture, ClearFixture
  CueValues values;     // SetFixture: one attribute set
};

}  // namespace haze
