// OSC remote control (docs/live.md, "Remote control"): one UDP datagram holding an OSC message,
// decoded with liblo, becomes one command for the live cue engine. The address space:
//   /haze/go                              GO: the next cue
//   /haze/back                            BACK: the previous cue
//   /haze/cue N   (or /haze/goto N)       GOTO cue N (a string "1.5", or a number)
//   /haze/fixture/ID/ATTRIBUTE V...       set a fixture's attribute over playback (programmer):
//                                         intensity 0..1, pan, tilt, zoom, gobo_rotation (degrees),
//                                         iris 0..1, color R G B (0..1 each), gobo NAME
//   /haze/fixture/ID/clear, /haze/clear   take one fixture or every fixture out of the programmer
//   /haze/camera NAME                     view the stage through the show's camera NAME
//   /haze/list/NAME/go, .../back          GO, BACK on the cue list NAME (several lists at once)
//   /haze/list/NAME/master V              that list's master, 0..1
// Pure bytes in: no sockets, never throws; bundles are refused (one message per datagram).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "shows/remote_command.h"

namespace haze {

struct OscParse {
  bool ok = false;
  std::string address;  // the message's OSC address, when there was one
  std::string error;    // why it was refused: for the reply and the log
  RemoteCommand command;
};

OscParse parseOscCommand(std::span<const uint8_t> datagram);

// The reply to a command: /haze/ok ADDRESS, or /haze/error ADDRESS MESSAGE (OSC bytes).
std::vector<uint8_t> oscReply(const OscParse& parse);

}  // namespace haze
