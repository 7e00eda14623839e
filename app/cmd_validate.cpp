// `haze validate SHOW`: every problem of a show, one line each on stderr ("file:pointer:
// sentence"), exit 1; a valid show prints a one-line summary on stdout and exits 0. Bad
// arguments exit 2.
#include <iostream>

#include "app/commands.h"
#include "shows/show_validate.h"

namespace haze {

namespace {
constexpr const char* kUsage = "usage: haze validate SHOW";
}

int runValidate(const Args& args) {
  std::string file;
  for (const std::string& a : args) {
    if (a == "--help" || a == "-h") {
      std::cout << kUsage << "\n  Checks a show file and its profiles; lists every problem with its JSON pointer.\n";
      return 0;
    }
    if (!a.empty() && a[0] == '-') {
      std::cerr << "haze validate: unknown option \"" << a << "\"; " << kUsage << "\n";
      return 2;
    }
    if (!file.empty()) {
      std::cerr << "haze validate: expected one show, got \"" << file << "\" and \"" << a << "\"; " << kUsage << "\n";
      return 2;
    }
    file = a;
  }
  if (file.empty()) {
    std::cerr << "haze validate: expected a show file; " << kUsage << "\n";
    return 2;
  }
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
