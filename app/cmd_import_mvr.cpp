// `haze import-mvr FILE.mvr -o SHOW.haze.json [--force] [--no-venue] [--verbose]`: turns an MVR
// rig into a haze show (shows/import/mvr_import.h). Warnings go to stderr with their XML place, those
// that say the same thing folded into one line with a count (--verbose: every one); an error is
// one line and exit 1; bad arguments exit 2.
#include <iostream>

#include "app/command_line.h"
#include "app/commands.h"
#include "fixtures/fixture_library.h"
#include "shows/import/mvr_import.h"

namespace haze {

namespace {
constexpr const char* kUsage =
    "usage: haze import-mvr FILE.mvr -o SHOW.haze.json [--force] [--no-venue] [--verbose] [--keep-embedded] [--library DIR]...";
}

int runImportMvr(const Args& args) {
  std::string input, output;
  MvrImportOptions options;
  bool verbose = false;
  CommandLine cli("haze import-mvr",
                  std::string(kUsage) +
                      "\n  Writes the show, SHOW_gdtf/ with the embedded GDTF files and SHOW_venue.gltf"
                      " (+ .bin) from the MVR's geometry, next to SHOW.\n  Warnings that say the same"
                      " thing are folded into one line with a count; --verbose prints every one.\n"
                      "  An embedded GDTF that is a stub (no wheels, channels Dimmer1..n) is replaced by the fixture\n"
                      "  library's fixture of the same name (haze fixture search); --keep-embedded keeps them all.\n");
  bool noVenue = false;
  cli.text("-o|--output", output, "a show file name")
      .flag("--force", options.force)
      .flag("--no-venue", noVenue)
      .flag("-v|--verbose", verbose)
      .flag("--keep-embedded", options.keepEmbedded)
      .custom("--library", "a folder of .qxf or .gdtf files",
              [&](const std::string& v) {
                options.extraLibraries.emplace_back(v);
                return !v.empty();
              })
      .positional(input, "MVR file");
  if (auto done = cli.parse(args)) return *done;
  if (noVenue) options.writeVenue = false;
  options.libraryCache = defaultLibraryCache();
  if (output.empty()) return cli.usage("expected an MVR file and -o SHOW; " + std::string(kUsage));
  auto result = importMvr(input, output, options);
  if (!result.ok()) {
    std::cerr << result.error().str() << "\n";
    return kExitBadInput;
  }
  for (const std::string& m : result->libraryMatches) std::cout << "fixture type " << m << "\n";
  const std::vector<std::string> shown = verbose ? result->warnings : groupMvrWarnings(result->warnings);
  for (const std::string& w : shown) std::cerr << "warning: " << input << ":" << w << "\n";
  std::cout << output << ": " << result->fixtureCount << " fixtures, " << result->show.profiles.size()
            << " GDTF profiles, " << result->geometryInstances << " venue meshes (" << result->venueTriangles
            << " triangles), " << result->warnings.size() << " warnings";
  if (shown.size() < result->warnings.size()) std::cout << " in " << shown.size() << " kinds (--verbose lists each)";
  std::cout << "\n";
  return 0;
}

}  // namespace haze
