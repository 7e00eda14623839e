// `haze export-mvr SHOW -o RIG.mvr [--force] [--focus-list NAME] [--focus-cue N]`: the show's rig as
// an MVR file (shows/import/mvr_export.h). Fixtures without an MVR uuid get one, saved in the show
// first, so the next export names them the same. What the file cannot carry is a warning on
// stderr; an error is one line and exit 1; bad arguments exit 2.
#include <iostream>

#include "app/command_line.h"
#include "app/commands.h"
#include "shows/import/mvr_export.h"

namespace haze {

namespace {
constexpr const char* kUsage = "usage: haze export-mvr SHOW -o RIG.mvr [--force] [--focus-list NAME] [--focus-cue N]";
}

int runExportMvr(const Args& args) {
  std::string input, output;
  MvrExportOptions options;
  CommandLine cli("haze export-mvr",
                  std::string(kUsage) +
                      "\n  Writes an MVR 1.6 file: every fixture with its uuid, ids, GDTF and mode, patch and placement,"
                      "\n  the show's groups, a focus point per fixture aimed by the focus cue (default: cue list"
                      "\n  \"MVR focus\", its first cue), the show's GDTF files and its other profiles written as GDTF."
                      "\n  A show imported from an MVR is written over that MVR (SHOW_source.mvr): its layers, trusses,"
                      "\n  scene objects and geometry stay. Fixtures without a uuid get one, saved in the show (its"
                      "\n  previous version stays as SHOW.bak).\n");
  cli.text("-o|--output", output, "an .mvr file name")
      .flag("--force", options.force)
      .text("--focus-list", options.focusList, "a cue list name")
      .text("--focus-cue", options.focusCue, "a cue number")
      .positional(input, "show file");
  if (auto done = cli.parse(args)) return *done;
  if (output.empty()) return cli.usage("expected a show and -o RIG.mvr; " + std::string(kUsage));
  // The show checked as every command checks it (haze validate's lines, exit 1).
  if (!cli.readShow(input)) return kExitBadInput;
  auto result = exportMvrFromShowFile(input, output, options);
  if (!result.ok()) return cli.fail(result.error().str());
  if (result->uuidsMade > 0) std::cerr << input << ": " << result->uuidsMade << " fixtures given an MVR uuid (saved in the show)\n";
  for (const std::string& w : result->warnings) std::cerr << "warning: " << output << ": " << w << "\n";
  std::cout << output << ": MVR " << result->version << ", " << result->fixtureCount
            << " fixtures, " << result->gdtfFiles << " GDTF files, " << result->focusPoints << " focus points, "
            << result->groupObjects << " groups, " << result->warnings.size() << " warnings";
  if (!result->source.empty())
    std::cout << "; over " << result->source << ": " << result->fixturesChanged << " fixtures moved, " << result->fixturesRemoved
              << " removed, " << result->filesKept << " files kept";
  std::cout << "\n";
  return 0;
}

}  // namespace haze
