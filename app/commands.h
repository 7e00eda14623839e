// The haze program's subcommands. main.cpp parses the first word and hands the rest over; each
// returns the process exit status and prints its own errors (one line each) to stderr.
#pragma once

#include <string>
#include <vector>

namespace haze {

using Args = std::vector<std::string>;  // the words after the subcommand

int runRender(const Args& args);        // app/cmd_render.cpp
int runFixture(const Args& args);       // app/cmd_fixture.cpp   (haze fixture info|search|change-type)
int runChangeType(const Args& args);    // app/cmd_change_type.cpp (haze fixture change-type SHOW ...)
int runState(const Args& args);         // app/cmd_state.cpp     (haze state SHOW --cue N ...)
int runValidate(const Args& args);      // app/cmd_validate.cpp  (haze validate SHOW)
int runBench(const Args& args);         // app/cmd_bench.cpp
int runCompare(const Args& args);       // app/cmd_compare.cpp   (haze compare IMAGE REFERENCE)
int runLive(const Args& args);          // app/cmd_live.cpp
int runImportMvr(const Args& args);     // app/cmd_import_mvr.cpp
int runSheet(const Args& args);         // app/cmd_sheet.cpp     (haze sheet SHOW -o SHEET.pdf)
int runVersion(const Args& args);       // app/cmd_version.cpp   (haze --version)
int runGui(const Args& args);           // app/gui/ (haze, haze open SHOW)

}  // namespace haze
