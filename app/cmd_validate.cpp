// `haze validate SHOW [--save-as OUT]`: every problem of a show, one line each on stderr
// ("file:pointer: sentence"), exit 1; a valid show prints a one-line summary on stdout (and a
// line saying so when an older format version was migrated) and exits 0. --save-as writes the
// valid show as read, in the newest format version, to OUT. A hazer outside the venue is a
// warning (the venue is read for that only). Bad arguments exit 2 (app/commands.h).
#include <iostream>

#include "shows/frame/atmosphere_field.h"
#include "app/command_line.h"
#include "app/commands.h"
#include "shows/scene/venue.h"
#include "shows/show_save.h"
#include "shows/show_validate.h"

namespace haze {

namespace {
constexpr const char* kUsage = "usage: haze validate SHOW [--save-as OUT]";

// Hazers are checked against the venue's box, which the show file alone does not give: the
// venue is read only for a show that has hazers. A warning, as `haze render` gives it.
void warnAboutHazers(const Show& show) {
  if (!show.atmosphere.density || show.atmosphere.density->hazers.empty() || show.venueGltf.empty()) return;
  auto venue = loadVenue(show.resolve(show.venueGltf));
  if (!venue) {
    std::cerr << "haze: warning: the hazers were not checked against the venue: " << venue.error().str() << "\n";
    return;
  }
  const DensityGrid grid = densityGrid(*show.atmosphere.density, venue->boundsMin, venue->boundsMax);
  for (const std::string& w : hazerWarnings(show, grid)) std::cerr << "haze: warning: " << w << "\n";
}
}  // namespace

int runValidate(const Args& args) {
  std::string file, saveAs;
  CommandLine cli("haze validate",
                  std::string(kUsage) +
                      "\n  Checks a show file and its profiles; lists every problem with its JSON pointer.\n"
                      "  --save-as OUT  write the valid show, in the newest format version, to OUT\n");
  cli.text("--save-as", saveAs, "a file to write the show to").positional(file, "show");
  if (auto done = cli.parse(args)) return *done;
  CheckedShow checked = checkShowFile(file);
  const std::vector<Error>& problems = checked.problems;
  for (const Error& e : problems) std::cerr << e.str() << "\n";
  if (!problems.empty()) {
    std::cerr << file << ": " << problems.size() << (problems.size() == 1 ? " problem" : " problems") << "\n";
    return kExitBadInput;
  }
  Show& show = checked.show;
  size_t cues = 0;
  for (const CueList& l : show.cueLists) cues += l.cues.size();
  std::cout << file << ": valid (" << show.fixtures.size() << " fixtures, " << show.groups.size() << " groups, "
            << show.palettes.size() << " palettes, " << show.cueLists.size() << " cue lists, " << cues << " cues)\n";
  if (show.fileVersion < kShowFormatVersion)
    std::cout << file << ": format version " << show.fileVersion << ", migrated to version " << kShowFormatVersion
              << " as it was read (version 2 adds groups and palettes; nothing else changes); saving writes version "
              << kShowFormatVersion << "\n";
  warnAboutHazers(show);
  if (!saveAs.empty()) {
    SaveOptions options;
    options.keepBackup = false;
    if (Status saved = saveShow(show, saveAs, options); !saved) {
      std::cerr << saved.error().str() << "\n";
      return kExitBadInput;
    }
    std::cout << saveAs << ": written (format version " << kShowFormatVersion << ")\n";
  }
  return 0;
}

}  // namespace haze
