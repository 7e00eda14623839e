// `haze validate SHOW`: every problem of a show, one line each on stderr ("file:pointer:
// sentence"), exit 1; a valid show prints a one-line summary on stdout and exits 0. Bad
// arguments exit 2.
#include <iostream>

#include "app/command_line.h"
#include "app/commands.h"
#include "shows/show_validate.h"

namespace haze {

namespace {
constexpr const char* kUsage = "usage: haze validate SHOW";
}

int runValidate(const Args& args) {
  std::string file;
  CommandLine cli("haze validate", std::string(kUsage) + "\n  Checks a show file and its profiles; lists every problem with its JSON pointer.\n", 2);
  cli.positional(file, "show");
  if (auto done = cli.parse(args)) return *done;
  std::vector<Error> problems = validateShowFile(file);
  for (const Error& e : problems) std::cerr << e.str() << "\n";
  if (!problems.empty()) {
    std::cerr << file << ": " << problems.size() << (problems.size() == 1 ? " problem" : " problems") << "\n";
    return 1;
  }
  auto show = loadShow(file);
  size_t cues = 0;
  if (show)
    for (const CueList& l : show->cueLists) cues += l.cues.size();
  std::cout << file << ": valid (" << (show ? show->fixtures.size() : 0) << " fixtures, "
            << (show ? show->cueLists.size() : 0) << " cue lists, " << cues << " cues)\n";
  return 0;
}

}  // namespace haze
