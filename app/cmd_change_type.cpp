// `haze fixture change-type SHOW --fixtures 11-20 --type TEXT [--mode M] [-o OUT]`: the fixtures
// get another type (a profile file, or the best match of TEXT in the fixture library), keeping
// id, name, position, orientation and patch start (shows/edit/edit_change_type.h). What could not
// be carried over is printed one line each; an overlap in the new footprints refuses the change.
#include <cstdlib>
#include <iostream>
#include <sstream>

#include "app/command_line.h"
#include "app/commands.h"
#include "fixtures/fixture_library.h"
#include "shows/edit/show_document.h"
#include "shows/show_json.h"

namespace haze {

namespace {

constexpr const char* kUsage =
    "usage: haze fixture change-type SHOW --fixtures LIST --type TEXT [--mode M] [-o OUT] [--library DIR]... [--force]\n"
    "  LIST: ids and ranges, \"11-20,23\"; TEXT: a profile file, or words naming a fixture in the library\n"
    "  (haze fixture search TEXT); M: one of its modes (default its first). Without -o the show is\n"
    "  saved in place (the old one kept as SHOW.bak). --verify-undo also checks that undoing the\n"
    "  change gives the show back byte for byte.";

// "11-20,23" or "11 thru 20": sorted ids.
std::optional<std::vector<int>> parseIds(std::string text) {
  for (size_t at; (at = text.find("thru")) != std::string::npos;) text.replace(at, 4, "-");
  std::vector<int> ids;
  std::stringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    std::erase(item, ' ');
    if (item.empty()) continue;
    const size_t dash = item.find('-', 1);
    char* end = nullptr;
    const long a = std::strtol(item.c_str(), &end, 10);
    long b = a;
    if (dash == std::string::npos) {
      if (*end) return std::nullopt;
    } else {
      if (end != item.c_str() + dash) return std::nullopt;
      b = std::strtol(item.c_str() + dash + 1, &end, 10);
      if (*end) return std::nullopt;
    }
    if (a < 1 || b < a || b - a > 100000) return std::nullopt;
    for (long id = a; id <= b; ++id) ids.push_back(static_cast<int>(id));
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  if (ids.empty()) return std::nullopt;
  return ids;
}

}  // namespace

int runChangeType(const Args& args) {
  std::string showFile, fixtures, type, mode, out;
  bool force = false, verifyUndo = false;
  std::vector<std::filesystem::path> extra;
  CommandLine cli("haze fixture change-type", std::string(kUsage) + "\n");
  cli.text("--fixtures", fixtures, "fixture ids (\"11-20,23\")").text("--type", type, "a profile file or a library fixture's name");
  cli.text("--mode", mode, "a mode of the new type").text("-o|--output", out, "a file to save the show to");
  cli.flag("--force", force).flag("--verify-undo", verifyUndo);
  cli.custom("--library", "a folder of .qxf or .gdtf files", [&](const std::string& v) {
    extra.emplace_back(v);
    return !v.empty();
  });
  cli.positional(showFile, "show");
  if (auto done = cli.parse(args)) return *done;
  if (fixtures.empty() || type.empty()) return cli.fail("--fixtures and --type are required; " + std::string(kUsage));
  auto ids = parseIds(fixtures);
  if (!ids) return cli.fail("--fixtures \"" + fixtures + "\" is not a list of ids; expected e.g. \"11-20,23\"");
  std::string chosen;
  auto file = resolveFixtureType(type, extra, &chosen);
  if (!file) return cli.fail(file.error().message);
  auto doc = ShowDocument::open(showFile);
  if (!doc) {
    std::cerr << doc.error().str() << "\n";
    return 1;
  }
  const std::string before = showToText((*doc)->show());
  auto report = (*doc)->changeFixtureType(*ids, *file, mode);
  if (!report) {
    std::cerr << showFile << ": " << report.error().str() << "\n";
    return 1;
  }
  const FixtureDef* first = (*doc)->show().findFixture(ids->front());
  std::cout << "changed " << ids->size() << (ids->size() == 1 ? " fixture" : " fixtures") << " to " << chosen << " (" << file->string()
            << "), mode \"" << (first ? first->mode : mode) << "\"; " << report->valuesMapped << " entries mapped, "
            << report->lines.size() << " not carried over as they were" << (report->lines.empty() ? "" : ":") << "\n";
  for (const std::string& line : report->lines) std::cout << "  " << line << "\n";
  if (verifyUndo) {
    const std::string after = showToText((*doc)->show());
    if (!(*doc)->undo() || showToText((*doc)->show()) != before) {
      std::cerr << showFile << ": undo did not give the show back as it was\n";
      return 1;
    }
    if (!(*doc)->redo() || showToText((*doc)->show()) != after) {
      std::cerr << showFile << ": redo did not give the changed show back\n";
      return 1;
    }
    std::cout << "undo gives the show back byte for byte (" << before.size() << " bytes)\n";
  }
  if (auto s = (*doc)->save(out.empty() ? std::filesystem::path(showFile) : std::filesystem::path(out), force); !s) {
    std::cerr << s.error().str() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace haze
