// `haze state SHOW --cue N [--at S] [--list NAME] [--follow] [--json]`: every fixture's attributes
// S seconds after GO into cue N from the full state of the cue before it (show-format.md). With
// --follow, follows fire as they would on stage (cue N's follow may GO the next cue, and so on).
// Bad arguments or a broken show give one line on stderr and exit 1 (2 for usage).
#include <charconv>
#include <cmath>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "shows/cue_player.h"
#include "shows/playback.h"
#include "shows/show_json.h"

namespace haze {

namespace {

constexpr const char* kUsage = "usage: haze state SHOW --cue N [--at S] [--list NAME] [--follow] [--json]";

int usage(const std::string& what) {
  std::cerr << "haze state: " << what << "; " << kUsage << "\n";
  return 2;
}

bool parseSeconds(const std::string& s, double& out) {
  const char* end = s.data() + s.size();
  auto [p, ec] = std::from_chars(s.data(), end, out);
  return ec == std::errc() && p == end && std::isfinite(out) && out >= 0.0;
}

nlohmann::ordered_json attributesJson(const Attributes& a, std::optional<float> fieldAngleDeg) {
  nlohmann::ordered_json o;
  o["intensity"] = tidy(a.intensity);
  o["pan"] = tidy(a.panDeg);
  o["tilt"] = tidy(a.tiltDeg);
  o["color"] = {tidy(a.color.r), tidy(a.color.g), tidy(a.color.b)};
  std::optional<float> zoom = a.zoomDeg ? a.zoomDeg : fieldAngleDeg;
  o["zoom"] = zoom ? nlohmann::ordered_json(tidy(*zoom)) : nlohmann::ordered_json(nullptr);
  o["gobo"] = a.gobo;
  o["gobo_rotation"] = tidy(a.goboRotationDeg);
  o["iris"] = tidy(a.iris);
  return o;
}

}  // namespace

int runState(const Args& args) {
  std::string file, cueNumber, listName;
  double atS = 1e9;  // no --at: the cue's full state
  bool json = false, follow = false, haveCue = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string& out) {
      if (i + 1 >= args.size()) return false;
      out = args[++i];
      return true;
    };
    if (a == "--help" || a == "-h") {
      std::cout << kUsage << "\n"
                << "  The state of every fixture S seconds after GO into cue N (default: the cue's full state).\n"
                << "  --list NAME  the cue list (default: the first)\n"
                << "  --follow     let follows fire after cue N, as on stage\n"
                << "  --json       {\"<fixture id>\": {\"intensity\", \"pan\", \"tilt\", \"color\", \"zoom\", \"gobo\", "
                   "\"gobo_rotation\", \"iris\"}}\n";
      return 0;
    } else if (a == "--cue") {
      if (!value(cueNumber)) return usage("--cue needs a cue number");
      haveCue = true;
    } else if (a == "--at") {
      std::string s;
      if (!value(s)) return usage("--at needs a time in seconds");
      if (!parseSeconds(s, atS)) return usage("--at expects seconds (a number, not negative), got \"" + s + "\"");
    } else if (a == "--list") {
      if (!value(listName)) return usage("--list needs a cue list name");
    } else if (a == "--json") {
      json = true;
    } else if (a == "--follow") {
      follow = true;
    } else if (!a.empty() && a[0] == '-') {
      return usage("unknown option \"" + a + "\"");
    } else if (file.empty()) {
      file = a;
    } else {
      return usage("expected one show, got \"" + file + "\" and \"" + a + "\"");
    }
  }
  if (file.empty()) return usage("expected a show file");
  if (!haveCue) return usage("expected --cue N");

  auto show = loadShow(file);
  if (!show) {
    std::cerr << show.error().str() << "\n";
    return 1;
  }
  auto profiles = loadProfiles(*show);
  if (!profiles) {
    std::cerr << profiles.error().str() << "\n";
    return 1;
  }
  const CueList* list = show->findCueList(listName);
  if (!list) {
    std::cerr << file << ": " << (listName.empty() ? "the show has no cue lists" : "no cue list \"" + listName + "\"")
              << "\n";
    return 1;
  }
  auto cue = findCue(*list, cueNumber);
  if (!cue) {
    std::cerr << file << ": " << cue.error().message << "\n";
    return 1;
  }

  StageState state;
  if (follow) {
    CuePlayer player(*show, *profiles, *list);
    if (*cue > 0) player.jumpTo(*cue - 1, 0.0);
    player.gotoCue(*cue, 0.0);
    state = player.state(atS);
  } else {
    state = stateAt(*show, *profiles, *list, *cue, atS);
  }

  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [id, attributes] : state) {
    std::optional<float> field;
    if (const FixtureDef* f = show->findFixture(id)) {
      auto p = profiles->find(f->profile);
      if (p != profiles->end()) field = p->second->fieldAngleDeg;
    }
    out[std::to_string(id)] = attributesJson(attributes, field);
  }
  if (json) {
    std::cout << out.dump(2) << "\n";
  } else {
    for (const auto& [id, a] : out.items()) {
      std::cout << id;
      for (const auto& [k, v] : a.items()) std::cout << "  " << k << " " << v.dump();
      std::cout << "\n";
    }
  }
  return 0;
}

}  // namespace haze
