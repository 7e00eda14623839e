// Running a command line (shows/edit/command_syntax.h) on an open show. What changes the show or
// the programmer is one command through ShowDocument::run, so one undo step per line, named by
// the line; selecting and playback (cue, go) change no show data and are not undo steps, as a
// click in the fixture list or GO are not. A line that fails changes nothing at all.
#pragma once

#include <string>

#include "shows/edit/show_document.h"

namespace haze {

// What the line did, for the status line ("Set 11 fixtures (1-3, 5-12): intensity 50 %"), or the
// error (parse errors name the word, see parseCommand).
Result<std::string> runCommandLine(ShowDocument& doc, const std::string& line, double nowS);

// "1-3, 5, 7-12": sorted fixture ids with runs folded.
std::string describeIds(const std::vector<int>& sortedIds);

}  // namespace haze
