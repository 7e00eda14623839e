// `haze fixture info FILE [--mode M] [--json]`: the facts of any profile file (native JSON, IES,
// LDT, GDTF, QLC+ .qxf) on stdout; `haze fixture search TEXT` looks in the fixture library
// (fixtures/fixture_library.h); `haze fixture list SHOW` lists a show's fixtures by id;
// `haze fixture change-type` gives fixtures of a show another type
// (app/cmd_change_type.cpp). A bad file or bad arguments give one line on stderr and exit status 1.
#include <chrono>
#include <cstdio>
#include <iostream>

#include "app/command_line.h"
#include "app/commands.h"
#include "fixtures/facts.h"
#include "fixtures/fixture_library.h"
#include "fixtures/profile.h"
#include "shows/edit/fixture_rows.h"

namespace haze {

namespace {

constexpr const char* kUsage = "usage: haze fixture info FILE [--mode M] [--json]";
constexpr const char* kSearchUsage =
    "usage: haze fixture search TEXT [--library DIR]... [--limit N] [--json] [--stats]\n"
    "  looks in the installed QLC+ definitions, the folders of HAZE_FIXTURE_PATH (':' between them)\n"
    "  and each --library DIR (.qxf and .gdtf); case, spaces and hyphens are ignored";
constexpr const char* kListUsage =
    "usage: haze fixture list SHOW [--json]\n"
    "  every fixture of the show by id: name, type, mode, universe.address (\"-\": unpatched)";
constexpr const char* kSubcommands = "expected the subcommand \"info\", \"search\", \"list\" or \"change-type\"";

void printText(const nlohmann::ordered_json& f) {
  auto num = [&](const char* k) { return f[k].get<double>(); };
  std::cout << f["name"].get<std::string>() << " (" << f["manufacturer"].get<std::string>() << ")\n"
            << "  peak " << num("peak_candela") << " cd, " << num("lumens") << " lm\n"
            << "  beam " << num("beam_angle") << " deg (C0 " << num("beam_angle_c0") << ", C90 " << num("beam_angle_c90") << ")\n"
            << "  field " << num("field_angle") << " deg (C0 " << num("field_angle_c0") << ", C90 " << num("field_angle_c90") << ")\n"
            << "  symmetry " << f["symmetry"].get<std::string>() << ", grid " << f["grid"]["gamma"].get<int>() << " gamma x "
            << f["grid"]["c"].get<int>() << " C\n"
            << "  lens radius " << num("lens_radius") << " m (" << f["lens_radius_source"].get<std::string>() << ")\n";
  for (const char* axis : {"pan", "tilt", "zoom"}) {
    const auto& m = f["movement"][axis];
    std::cout << "  " << axis << " speed " << m["speed"].get<double>() << " deg/s, acceleration "
              << m["acceleration"].get<double>() << " deg/s^2 (" << m["source"].get<std::string>() << ")\n";
  }
  if (!f["cells"].empty()) std::cout << "  " << f["cells"].size() << " cells:\n";
  for (const auto& c : f["cells"]) {
    std::cout << "    " << c["cell"].get<int>() << " " << c["name"].get<std::string>() << ": lens at ["
              << c["lens_offset"][0].get<double>() << ", " << c["lens_offset"][1].get<double>() << ", "
              << c["lens_offset"][2].get<double>() << "] m, field " << c["field_angle"].get<double>() << " deg, "
              << c["lumens"].get<double>() << " lm\n";
  }
  {
    const auto& b = f["body"];
    std::cout << "  body (" << b["source"].get<std::string>() << "):";
    for (const char* part : {"base", "yoke_left", "head"}) {
      if (b[part].is_null()) continue;
      const auto& size = b[part]["size"];
      std::cout << " " << (std::string(part) == "yoke_left" ? "yoke arm" : part) << " " << size[0].get<double>() << " x "
                << size[1].get<double>() << " x " << size[2].get<double>() << " m";
    }
    std::cout << "\n";
    for (const auto& m : b["models"]) {
      const auto& size = m["size"];
      std::cout << "    " << m["part"].get<std::string>() << " model " << m["file"].get<std::string>() << ": "
                << m["triangles"].get<std::size_t>() << " triangles, " << size[0].get<double>() << " x "
                << size[1].get<double>() << " x " << size[2].get<double>() << " m\n";
    }
  }
  for (auto [key, what] : {std::pair{"gobo_wheels", "gobo wheel"}, std::pair{"color_wheels", "colour wheel"},
                            std::pair{"animation_wheels", "animation wheel"}})
    for (size_t w = 0; w < f[key].size(); ++w) {
      const auto& wheel = f[key][w];
      std::cout << "  " << what << " " << w + 1 << " \"" << wheel["name"].get<std::string>() << "\": " << wheel["slots"].size()
                << " slots:";
      for (const auto& s : wheel["slots"]) std::cout << " \"" << s.get<std::string>() << "\"";
      std::cout << "\n";
    }
  // Beam optics beyond the gobo.
  if (!f["frost"].is_null()) std::cout << "  frost up to " << f["frost"]["max"].get<double>() << " deg\n";
  if (!f["focus"].is_null())
    std::cout << "  focus: sharp at " << f["focus"]["sharp"].get<double>() << ", blur " << f["focus"]["blur"].get<double>()
              << " gate radii per unit of focus\n";
  for (const auto& p : f["prisms"])
    std::cout << "  prism \"" << p["name"].get<std::string>() << "\": " << p["facets"].get<int>() << " facets"
              << (p["linear"].get<bool>() ? " linear" : "") << ", " << p["deflection"].get<double>() << " deg\n";
  if (f["blades"].get<bool>()) std::cout << "  framing blades\n";
  if (!f["shutter"].is_null()) {
    std::cout << "  shutter";
    for (const auto& m : f["shutter"]["modes"]) std::cout << " " << m.get<std::string>();
    std::cout << " (up to " << f["shutter"]["max_hz"].get<double>() << " Hz)\n";
  }
  if (f.contains("defaults")) {
    std::cout << "  defaults (not in the file):";
    for (const auto& d : f["defaults"]) std::cout << " " << d.get<std::string>();
    std::cout << "\n";
  }
}

int runSearch(const Args& args) {
  std::string query;
  bool json = false, stats = false;
  int limit = 0;
  std::vector<std::filesystem::path> extra;
  CommandLine cli("haze fixture search", std::string(kSearchUsage) + "\n");
  cli.flag("--json", json).flag("--stats", stats).integer("--limit", limit, 0, 1000000, "a count (0 = all)");
  cli.custom("--library", "a folder of .qxf or .gdtf files", [&](const std::string& v) {
    extra.emplace_back(v);
    return !v.empty();
  });
  cli.positional(query, "text");
  if (auto done = cli.parse(args)) return *done;
  const auto t0 = std::chrono::steady_clock::now();
  const LibraryIndex index = indexLibrary(libraryFolders(extra), defaultLibraryCache());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const std::string& w : index.warnings) std::cerr << "warning: " << w << "\n";
  if (stats)
    std::fprintf(stderr, "library: %zu files (%d read, %d from the cache) in %.3f s\n", index.entries.size(), index.readNow,
                 index.fromCache, seconds);
  std::vector<const LibraryEntry*> hits = searchLibrary(index, query);
  if (limit > 0 && hits.size() > static_cast<size_t>(limit)) hits.resize(static_cast<size_t>(limit));
  if (json) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const LibraryEntry* e : hits) {
      nlohmann::ordered_json j;
      j["manufacturer"] = e->manufacturer;
      j["name"] = e->name;
      j["type"] = e->type;
      j["file"] = e->file;
      j["format"] = e->format;
      nlohmann::ordered_json modes = nlohmann::ordered_json::array();
      for (const LibraryEntry::Mode& m : e->modes) modes.push_back({{"name", m.name}, {"channels", m.channels}});
      j["modes"] = modes;
      j["lens_degrees"] = e->degreesMax > 0 ? nlohmann::ordered_json{e->degreesMin, e->degreesMax} : nlohmann::ordered_json(nullptr);
      j["lumens"] = e->lumens > 0 ? nlohmann::ordered_json(e->lumens) : nlohmann::ordered_json(nullptr);
      j["weight"] = e->weightKg > 0 ? nlohmann::ordered_json(e->weightKg) : nlohmann::ordered_json(nullptr);
      j["power"] = e->powerW > 0 ? nlohmann::ordered_json(e->powerW) : nlohmann::ordered_json(nullptr);
      out.push_back(j);
    }
    std::cout << out.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
    return 0;
  }
  if (hits.empty()) std::cout << "no fixture in the library matches \"" << query << "\"\n";
  for (const LibraryEntry* e : hits) {
    std::cout << e->title() << "  (" << e->type;
    if (e->degreesMax > 0)
      std::cout << ", " << (e->degreesMin > 0 && e->degreesMin != e->degreesMax ? std::to_string(static_cast<int>(e->degreesMin)) + "-" : "")
                << static_cast<int>(e->degreesMax) << " deg";
    if (e->lumens > 0) std::cout << ", " << static_cast<int>(e->lumens) << " lm";
    std::cout << ")\n    modes:";
    for (size_t k = 0; k < e->modes.size(); ++k)
      std::cout << (k ? "," : "") << " \"" << e->modes[k].name << "\" " << e->modes[k].channels << " ch";
    std::cout << "\n    " << e->file << "\n";
  }
  return 0;
}

// A show's fixtures as a table (or JSON), sorted by id: what a designer checks a rig by.
int runList(const Args& args) {
  std::string file;
  bool json = false;
  CommandLine cli("haze fixture list", std::string(kListUsage) + "\n");
  cli.flag("--json", json).positional(file, "show");
  if (auto done = cli.parse(args)) return *done;
  auto checked = cli.readShow(file);
  if (!checked) return kExitBadInput;
  const std::vector<FixtureRow> rows = fixtureRows(checked->show, checked->profiles);
  auto patchOf = [](const FixtureRow& r) {
    return r.patch ? std::to_string(r.patch->universe) + "." + std::to_string(r.patch->address) : std::string("-");
  };
  if (json) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const FixtureRow& r : rows) {
      nlohmann::ordered_json j;
      j["id"] = r.id;
      j["name"] = r.name;
      j["type"] = r.type;
      j["mode"] = r.mode;
      j["universe"] = r.patch ? nlohmann::ordered_json(r.patch->universe) : nlohmann::ordered_json(nullptr);
      j["address"] = r.patch ? nlohmann::ordered_json(r.patch->address) : nlohmann::ordered_json(nullptr);
      j["channels"] = r.channels ? nlohmann::ordered_json(*r.channels) : nlohmann::ordered_json(nullptr);
      out.push_back(j);
    }
    std::cout << out.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
    return 0;
  }
  // Columns as wide as their longest entry, so the list reads down.
  std::size_t wId = 2, wName = 4, wType = 4, wMode = 4;
  for (const FixtureRow& r : rows) {
    wId = std::max(wId, std::to_string(r.id).size());
    wName = std::max(wName, r.name.size());
    wType = std::max(wType, r.type.size());
    wMode = std::max(wMode, r.mode.size());
  }
  auto line = [&](const std::string& id, const std::string& name, const std::string& type, const std::string& mode,
                  const std::string& patch) {
    std::cout << std::string(wId - id.size(), ' ') << id << "  " << name << std::string(wName - name.size(), ' ') << "  " << type
              << std::string(wType - type.size(), ' ') << "  " << mode << std::string(wMode - mode.size(), ' ') << "  " << patch << "\n";
  };
  line("id", "name", "type", "mode", "univ.addr");
  for (const FixtureRow& r : rows) line(std::to_string(r.id), r.name, r.type, r.mode, patchOf(r));
  return 0;
}

}  // namespace

int runFixture(const Args& args) {
  if (!args.empty() && args[0] == "list") return runList(Args(args.begin() + 1, args.end()));
  if (!args.empty() && args[0] == "search") return runSearch(Args(args.begin() + 1, args.end()));
  if (!args.empty() && args[0] == "change-type") return runChangeType(Args(args.begin() + 1, args.end()));
  if (args.empty() || args[0] != "info") {
    std::cerr << "haze fixture: " << kSubcommands << "; " << kUsage << "\n";
    return kExitUsage;
  }
  std::string file, mode;
  bool json = false;
  CommandLine cli("haze fixture info", std::string(kUsage) + "\n");
  cli.flag("--json", json).text("--mode", mode, "a mode name").positional(file, "file");
  if (auto done = cli.parse(Args(args.begin() + 1, args.end()))) return *done;
  auto profile = loadProfile(file);
  if (!profile) {
    std::cerr << profile.error().str() << "\n";
    return 1;
  }
  // What reading the profile clamped (prisms, frost beyond haze's ranges) is said, not dropped.
  for (const std::string& w : (*profile)->warnings) std::cerr << "warning: " << w << "\n";
  nlohmann::ordered_json facts = fixtureFacts(**profile);
  if (!mode.empty()) {  // the one mode asked for
    nlohmann::ordered_json kept = nlohmann::ordered_json::array();
    std::string names;
    for (const auto& m : facts["modes"]) {
      if (m["name"] == mode) kept.push_back(m);
      names += (names.empty() ? "\"" : ", \"") + m["name"].get<std::string>() + "\"";
    }
    if (kept.empty()) {
      std::cerr << file << ": no mode \"" << mode << "\"; its modes are: " << names << "\n";
      return 1;
    }
    facts["modes"] = kept;
  }
  if (json)
    std::cout << facts.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
  else
    printText(facts);
  return 0;
}

}  // namespace haze
