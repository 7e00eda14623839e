// `haze import-mvr FILE.mvr -o SHOW.haze.json [--force] [--no-venue] [--verbose]`: turns an MVR
// rig into a haze show (shows/mvr_import.h). Warnings go to stderr with their XML place, those
// that say the same thing folded into one line with a count (--verbose: every one); an error is
// one line and exit 1; bad arguments exit 2.
#include <iostream>

#include "app/commands.h"
#include "shows/mvr_import.h"

namespace haze {

namespace {
constexpr const char* kUsage = "usage: haze import-mvr FILE.mvr -o SHOW.haze.json [--force] [--no-venue] [--verbose]";
}

int runImportMvr(const Args& args) {
  std::string input, output;
  MvrImportOptions options;
  bool verbose = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      std::cout << kUsage << "\n  Writes the show, SHOW_gdtf/ with the embedded GDTF files and SHOW_venue.gltf"
                             " (+ .bin) from the MVR's geometry, next to SHOW.\n  Warnings that say the same"
                             " thing are folded into one line with a count; --verbose prints every one.\n";
      return 0;
    }
    if (a == "-o" || a == "--output") {
      if (i + 1 >= args.size()) {
        std::cerr << "haze import-mvr: " << a << " needs a show file name; " << kUsage << "\n";
        return 2;
      }
      output = args[++i];
    } else if (a == "--force") {
      options.force = true;
    } else if (a == "--no-venue") {
      options.writeVenue = false;
    } else if (a == "--verbose" || a == "-v") {
      verbose = true;
    } else if (!a.empty() && a[0] == '-') {
      std::cerr << "haze import-mvr: unknown option \"" << a << "\"; " << kUsage << "\n";
      return 2;
    } else if (!input.empty()) {
      std::cerr << "haze import-mvr: expected one MVR file, got \"" << input << "\" and \"" << a << "\"; " << kUsage << "\n";
      return 2;
    } else {
      input = a;
    }
  }
  if (input.empty() || output.empty()) {
    std::cerr << "haze import-mvr: expected an MVR file and -o SHOW; " << kUsage << "\n";
    return 2;
  }
  auto result = importMvr(input, output, options);
  if (!result.ok()) {
    std::cerr << result.error().str() << "\n";
    return 1;
  }
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
