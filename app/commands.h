// The haze program's subcommands. main.cpp parses the first word and hands the rest over; each
// returns the process exit status and prints its own errors (one line each) to stderr.
#pragma once

#include <string>
#include <vector>

namespace haze {

using Args = std::vector<std::string>;  // the words after the subcommand

// Every command's exit status (listed in `haze --help`): 0 done; 1 bad input (a file, a show that
// `haze validate` refuses, a device, an output that cannot be written); 2 a usage error (an unknown
// command or option, a bad option value, options that do not go together, a missing argument).
// `haze compare` adds 3 for an error above --max-error.
inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 1;
inline constexpr int kExitUsage = 2;

int runRender(const Args& args);        // app/cmd_render.cpp
int runFixture(const Args& args);       // app/cmd_fixture.cpp   (haze fixture info|search|change-type)
int runChangeType(const Args& args);    // app/cmd_change_type.cpp (haze fixture change-type SHOW ...)
int runState(const Args& args);         // app/cmd_state.cpp     (haze state SHOW --cue N ...)
int runValidate(const Args& args);      // app/cmd_validate.cpp  (haze validate SHOW)
int runBench(const Args& args);         // app/cmd_bench.cpp
int runCompare(const Args& args);       // app/cmd_compare.cpp   (haze compare IMAGE REFERENCE)
int runLive(const Args& args);          // app/cmd_live.cpp
int runImportMvr(const Args& args);     // app/cmd_import_mvr.cpp
int runExportMvr(const Args& args);     // app/cmd_export_mvr.cpp   (haze export-mvr SHOW -o RIG.mvr)
int runSheet(const Args& args);         // app/cmd_sheet.cpp     (haze sheet SHOW -o SHEET.pdf)
int runFarm(const Args& args);          // app/cmd_farm.cpp      (haze farm slurm|status|encode)
int runVersion(const Args& args);       // app/cmd_version.cpp   (haze --version)
int runGui(const Args& args);           // app/gui/ (haze, haze open SHOW)

}  // namespace haze
